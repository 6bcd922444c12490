#pragma once
/// PNG files and contact sheets of RGB8 images (tightly packed, row-major, top row first).

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/status.h"

namespace simhuman::render {

/// Writes a w x h RGB8 image as an 8-bit RGB PNG. Errors: kInvalidArgument when rgb.size() is
/// not w*h*3, kNotFound / kPermissionDenied / kInternal (naming `path`) when the file cannot
/// be written.
absl::Status WritePng(const std::string& path, const std::vector<uint8_t>& rgb, int w, int h);

/// Reads a PNG of any bit depth and colour type into RGB8 (alpha is dropped, grey expanded,
/// 16-bit reduced). Errors name `path`: kNotFound, kInvalidArgument for a file that is not a
/// valid PNG.
absl::Status ReadPng(const std::string& path, std::vector<uint8_t>* rgb, int* w, int* h);

/// Layout of a contact sheet.
struct ContactSheetOptions {
  int cols = 4;       // frames per row, >= 1
  int downscale = 1;  // each frame shrinks by this integer factor (box filter), >= 1
  int border_px = 2;  // white border around and between frames, >= 0
};

/// Tiles `frames` (each w x h RGB8) row by row into a grid of `options.cols` columns (fewer
/// when there are fewer frames). Cells are (w / downscale) x (h / downscale), separated and
/// surrounded by white borders; unused cells stay white. The sheet goes to `*sheet`, its size
/// to `*sheet_w` = cols * cell_w + (cols + 1) * border_px and `*sheet_h` (likewise for rows).
/// Errors: kInvalidArgument for no frames, a frame of the wrong size (named by its index), or
/// bad options.
absl::Status MakeContactSheet(const std::vector<std::vector<uint8_t>>& frames, int w, int h,
                              const ContactSheetOptions& options, std::vector<uint8_t>* sheet,
                              int* sheet_w, int* sheet_h);

/// MakeContactSheet with `cols` columns, then WritePng to `path`.
absl::Status WriteContactSheet(const std::string& path,
                               const std::vector<std::vector<uint8_t>>& frames, int w, int h,
                               int cols, int downscale = 1, int border_px = 2);

}  // namespace simhuman::render
