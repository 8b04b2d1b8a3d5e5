// contact_sheet.h — a labelled grid of downscaled frames, to review a whole sequence in one picture.
#pragma once

#include "phongvk/export.h"
#include "phongvk/image.h"

#include <string>
#include <vector>

namespace phongvk {

// `source` averaged down to width x height with a box filter: the source columns (and rows) are
// split into width (height) consecutive runs as even as integers allow, and each output pixel is
// the rounded mean of its run's pixels. Precondition: 1 <= width <= source.width, likewise height.
PHONGVK_API Image downscale(const Image& source, int width, int height);

// The size of a thumbnail of a width x height frame: at most maxWidth wide (never enlarged), the
// aspect kept, at least 1x1.
struct ThumbnailSize {
  int width;
  int height;
};
PHONGVK_API ThumbnailSize thumbnailSize(int width, int height, int maxWidth);

// Draws ASCII `text` (stb_easy_font) in white on a black box whose top-left corner is (x, y), each
// font pixel `scale` x `scale` image pixels, so it reads on any picture. Clipped to the image.
PHONGVK_API void drawLabel(Image& image, int x, int y, const std::string& text, int scale);

struct Thumbnail {
  int frame = 0;  // its index in the sequence, drawn on it
  Image image;
};

// The thumbnails (at least one) in rows of `columns`, in order, each labelled with its frame
// index, on a dark grey background with a small gap between them; cells fit the largest one.
PHONGVK_API Image contactSheet(const std::vector<Thumbnail>& thumbnails, int columns);

// Columns for a sheet of `count` thumbnails: close to square (ceil(sqrt(count))).
PHONGVK_API int sheetColumns(int count);

// The memory a sheet of `count` thumbnails, cells of `cell`, in sheetColumns(count) columns, takes
// while it is made and written: the thumbnails, the sheet and its encoding (as large again).
PHONGVK_API uint64_t contactSheetBytes(int count, ThumbnailSize cell);

}  // namespace phongvk
