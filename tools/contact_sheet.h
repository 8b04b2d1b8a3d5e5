// contact_sheet.h — a labelled grid of downscaled frames, to review a whole sequence in one picture
// (`phongvk sequence --contact-sheet`).
#pragma once

#include "phongvk/image.h"

#include <string>
#include <vector>

namespace phongvk {

// The size of a thumbnail of a width x height frame: at most maxWidth wide (never enlarged), the
// aspect kept, at least 1x1.
struct ThumbnailSize {
  int width;
  int height;
};
ThumbnailSize thumbnailSize(int width, int height, int maxWidth);

// Draws ASCII `text` (stb_easy_font) in white on a black box whose top-left corner is (x, y), each
// font pixel `scale` x `scale` image pixels, so it reads on any picture. Clipped to the image.
void drawLabel(Image& image, int x, int y, const std::string& text, int scale);

struct Thumbnail {
  int frame = 0;  // its index in the sequence, drawn on it
  Image image;
};

// The thumbnails (at least one) in rows of `columns`, in order, each labelled with its frame
// index, on a dark grey background with a small gap between them; cells fit the largest one.
Image contactSheet(const std::vector<Thumbnail>& thumbnails, int columns);

// Columns for a sheet of `count` thumbnails: close to square (ceil(sqrt(count))).
int sheetColumns(int count);

// The memory a sheet of `count` thumbnails, cells of `cell`, in sheetColumns(count) columns, takes
// while it is made and written: the thumbnails, the sheet and its encoding (as large again).
uint64_t contactSheetBytes(int count, ThumbnailSize cell);

}  // namespace phongvk
