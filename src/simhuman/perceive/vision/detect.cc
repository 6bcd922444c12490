#include "simhuman/perceive/vision/detect.h"

#include <algorithm>

#include "absl/strings/str_cat.h"

namespace simhuman::perceive {

const std::vector<std::string>& VisionColours() {
  static const std::vector<std::string> k = {"red", "yellow", "green", "blue"};
  return k;
}

const std::vector<std::string>& VisionShapes() {
  static const std::vector<std::string> k = {"box", "cylinder", "sphere"};
  return k;
}

void ColourTable::Add(const uint8_t* rgb, int label) {
  if (counts_.empty()) counts_.assign(kCells, {0, 0, 0, 0, 0});
  ++counts_[Cell(rgb)][label];
}

void ColourTable::Finish(double min_share) {
  if (counts_.empty()) return;
  for (int c = 0; c < kCells; ++c) {
    const std::array<uint32_t, 5>& n = counts_[c];
    uint32_t total = 0;
    int best = 0;
    for (int l = 0; l < 5; ++l) {
      total += n[l];
      if (n[l] > n[best]) best = l;
    }
    labels_[c] = (total > 0 && best > 0 && n[best] >= min_share * total) ? best : 0;
  }
}

core::Status ColourTable::SetLabels(const std::vector<uint8_t>& labels) {
  if (labels.size() != static_cast<size_t>(kCells)) {
    return absl::InvalidArgumentError(
        absl::StrCat("colour table has ", labels.size(), " cells; expected ", kCells));
  }
  for (uint8_t l : labels) {
    if (l > 4) {
      return absl::InvalidArgumentError(
          absl::StrCat("colour table label ", static_cast<int>(l), " is not in [0, 4]"));
    }
  }
  labels_ = labels;
  return absl::OkStatus();
}

std::vector<Blob> FindBlobs(const std::vector<uint8_t>& rgb, int width, int height,
                            const ColourTable& table, int min_pixels) {
  const int n = width * height;
  std::vector<int8_t> label(n);
  for (int i = 0; i < n; ++i) label[i] = static_cast<int8_t>(table.Classify(&rgb[3 * i]));
  std::vector<uint8_t> seen(n, 0);
  std::vector<Blob> out;
  std::vector<int> stack;
  for (int start = 0; start < n; ++start) {
    if (label[start] == 0 || seen[start]) continue;
    Blob b;
    b.colour = label[start] - 1;
    b.x0 = width;
    b.y0 = height;
    b.x1 = b.y1 = -1;
    stack.assign(1, start);
    seen[start] = 1;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      b.index.push_back(i);
      const int x = i % width, y = i / width;
      b.x0 = std::min(b.x0, x);
      b.x1 = std::max(b.x1, x);
      b.y0 = std::min(b.y0, y);
      b.y1 = std::max(b.y1, y);
      b.cu += x + 0.5;
      b.cv += y + 0.5;
      const int nb[4] = {x > 0 ? i - 1 : -1, x + 1 < width ? i + 1 : -1, y > 0 ? i - width : -1,
                         y + 1 < height ? i + width : -1};
      for (int j : nb) {
        if (j >= 0 && !seen[j] && label[j] == label[start]) {
          seen[j] = 1;
          stack.push_back(j);
        }
      }
    }
    b.pixels = static_cast<int>(b.index.size());
    if (b.pixels < min_pixels) continue;
    b.cu /= b.pixels;
    b.cv /= b.pixels;
    out.push_back(std::move(b));
  }
  std::sort(out.begin(), out.end(),
            [](const Blob& a, const Blob& b) { return a.pixels > b.pixels; });
  return out;
}

}  // namespace simhuman::perceive
