#pragma once
/// Finding the coloured objects in an egocentric RGB frame: a learned colour table classifies
/// each pixel (background or one of the tabletop colours), and 4-connected components of one
/// colour become blobs. This is the part DASH does with Mask R-CNN; on two CPU cores a
/// per-pixel table costs microseconds, and the blobs' attributes (shape, 3-D position, height,
/// up axis) come from the vision network (vision_model.h).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "simhuman/core/status.h"

namespace simhuman::perceive {

/// The colours and shapes the vision module knows (DASH's): indices into these lists are the
/// class ids used everywhere below.
const std::vector<std::string>& VisionColours();  ///< red, yellow, green, blue
const std::vector<std::string>& VisionShapes();   ///< box, cylinder, sphere

/// Per-pixel colour classes learned from rendered frames: RGB quantised to 32 levels per channel,
/// each cell holding the most frequent label seen there (0 background, 1 + colour index).
/// Cells never seen are background.
class ColourTable {
 public:
  static constexpr int kLevels = 32;
  static constexpr int kCells = kLevels * kLevels * kLevels;

  /// Counts one labelled pixel (label 0 background, 1..4 a colour).
  void Add(const uint8_t* rgb, int label);
  /// Turns the counts into labels: a cell is a colour when that colour's count is the largest
  /// and at least `min_share` of the cell's pixels.
  void Finish(double min_share = 0.6);
  int Classify(const uint8_t* rgb) const { return labels_[Cell(rgb)]; }

  const std::vector<uint8_t>& labels() const { return labels_; }
  /// Sets the labels (from a model file); InvalidArgument unless kCells labels in [0, 4].
  core::Status SetLabels(const std::vector<uint8_t>& labels);

 private:
  static int Cell(const uint8_t* rgb) {
    return ((rgb[0] >> 3) * kLevels + (rgb[1] >> 3)) * kLevels + (rgb[2] >> 3);
  }
  std::vector<uint8_t> labels_ = std::vector<uint8_t>(kCells, 0);
  std::vector<std::array<uint32_t, 5>> counts_;
};

/// One connected region of a single colour.
struct Blob {
  int colour = 0;                      ///< index into VisionColours()
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< bounding box, inclusive pixel indices
  int pixels = 0;
  double cu = 0, cv = 0;   ///< centroid (pixel coordinates, centres at +0.5)
  std::vector<int> index;  ///< pixel indices (y * width + x)
};

/// The blobs of `rgb` (width*height*3, top row first) with at least `min_pixels` pixels, largest
/// first.
std::vector<Blob> FindBlobs(const std::vector<uint8_t>& rgb, int width, int height,
                            const ColourTable& table, int min_pixels);

}  // namespace simhuman::perceive
