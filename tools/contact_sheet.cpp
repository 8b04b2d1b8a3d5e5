// contact_sheet.cpp — see contact_sheet.h.
#include "tools/contact_sheet.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>

#include <stb_easy_font.h>

namespace phongvk {
namespace {

constexpr int kGap = 4;                           // pixels between thumbnails and around them
constexpr uint8_t kSheetGrey = 40;                // background: dark, so frames stand out
constexpr int kLabelPadding = 1;                  // font pixels of box around the text
constexpr int kLargeLabelWidth = 240;             // thumbnails this wide get 2x labels

void fillRect(Image& image, int x0, int y0, int x1, int y1, uint8_t value) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, image.width);
  y1 = std::min(y1, image.height);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) std::memset(image.pixel(x, y), value, 3);
  }
}

void blit(Image& target, const Image& source, int x0, int y0) {
  for (int y = 0; y < source.height; ++y) {
    std::memcpy(target.pixel(x0, y0 + y), source.pixel(0, y), size_t(source.width) * 3);
  }
}

// stb_easy_font builds glyphs from axis-aligned quads of 4 vertices (x, y, z floats, 4 colour
// bytes); each quad is a rectangle in font pixels.
struct FontVertex {
  float x, y, z;
  uint8_t color[4];
};

}  // namespace

ThumbnailSize thumbnailSize(int width, int height, int maxWidth) {
  if (width <= maxWidth) return {width, height};
  const int scaledHeight = int(std::lround(double(height) * maxWidth / width));
  return {maxWidth, std::max(scaledHeight, 1)};
}

void drawLabel(Image& image, int x, int y, const std::string& text, int scale) {
  std::string chars = text;  // stb_easy_font takes a mutable char*
  std::vector<FontVertex> quads(chars.size() * 64 + 64);  // ~270 bytes per character, per its docs
  const int count = stb_easy_font_print(0, 0, chars.data(), nullptr, quads.data(),
                                        int(quads.size() * sizeof(FontVertex)));
  const int pad = kLabelPadding;
  // The font's glyphs span rows 0..7 of a 12-row line (ascenders to baseline; digits have no
  // descenders), so the box is cut to 7 rows plus padding rather than the full line height.
  const int boxWidth = stb_easy_font_width(chars.data()) + 2 * pad;
  const int boxHeight = 7 + 2 * pad;
  fillRect(image, x, y, x + boxWidth * scale, y + boxHeight * scale, 0);
  for (int q = 0; q < count; ++q) {
    const FontVertex& a = quads[q * 4];
    const FontVertex& c = quads[q * 4 + 2];
    auto at = [&](float font, int origin) { return origin + int(std::lround((font + pad) * scale)); };
    fillRect(image, at(a.x, x), at(a.y, y), at(c.x, x), at(c.y, y), 255);
  }
}

Image contactSheet(const std::vector<Thumbnail>& thumbnails, int columns) {
  assert(!thumbnails.empty() && columns >= 1);
  int tw = 0, th = 0;  // the cell: frames of a sequence may differ in size
  for (const Thumbnail& t : thumbnails) {
    tw = std::max(tw, t.image.width);
    th = std::max(th, t.image.height);
  }
  const int count = int(thumbnails.size());
  columns = std::min(columns, count);
  const int rows = (count + columns - 1) / columns;
  Image sheet(kGap + columns * (tw + kGap), kGap + rows * (th + kGap));
  std::fill(sheet.rgb.begin(), sheet.rgb.end(), kSheetGrey);
  const int scale = tw >= kLargeLabelWidth ? 2 : 1;
  for (int k = 0; k < count; ++k) {
    const Thumbnail& t = thumbnails[k];
    const int x = kGap + (k % columns) * (tw + kGap);
    const int y = kGap + (k / columns) * (th + kGap);
    blit(sheet, t.image, x, y);
    drawLabel(sheet, x, y, std::to_string(t.frame), scale);
  }
  return sheet;
}

int sheetColumns(int count) { return std::max(1, int(std::ceil(std::sqrt(double(count))))); }

uint64_t contactSheetBytes(int count, ThumbnailSize cell) {
  const uint64_t columns = std::min(sheetColumns(count), count);
  const uint64_t rows = (uint64_t(count) + columns - 1) / columns;
  const uint64_t sheet = (kGap + columns * (cell.width + kGap)) * (kGap + rows * (cell.height + kGap)) * 3;
  return uint64_t(count) * uint64_t(cell.width) * uint64_t(cell.height) * 3 + 2 * sheet;
}

}  // namespace phongvk
