// png_decode.cpp — decodePng (texture_codecs.h) with libpng. libpng reports errors by longjmp, so
// the calls that may jump sit in small functions with nothing to destroy; what they fail with is
// kept in PngStream and thrown from ordinary C++ afterwards.
#include "image/texture_codecs.h"

#include "phongvk/errors.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <utility>
#include <vector>

namespace phongvk {

namespace {

// The read state libpng's callbacks see: the bytes, how far it has read, and the first error.
struct PngStream {
  std::string_view bytes;
  size_t read = 0;
  char error[256] = "";
  char warning[256] = "";  // the last: libpng warns why before it fails with "Invalid IHDR data"
};

void onError(png_structp png, png_const_charp message) {
  auto* stream = static_cast<PngStream*>(png_get_error_ptr(png));
  std::snprintf(stream->error, sizeof stream->error, "%s", message);
  png_longjmp(png, 1);
}

// Kept for the message of an error that follows; alone, a warning (a bad sRGB chunk) leaves the
// pixels right.
void onWarning(png_structp png, png_const_charp message) {
  auto* stream = static_cast<PngStream*>(png_get_error_ptr(png));
  std::snprintf(stream->warning, sizeof stream->warning, "%s", message);
}

void onRead(png_structp png, png_bytep out, size_t count) {
  auto* stream = static_cast<PngStream*>(png_get_io_ptr(png));
  if (count > stream->bytes.size() - stream->read) png_error(png, "the file ends early (truncated)");
  std::memcpy(out, stream->bytes.data() + stream->read, count);
  stream->read += count;
}

// The chunks up to the pixels; false with PngStream::error set on an error.
bool readHeader(png_structp png, png_infop info, png_uint_32& width, png_uint_32& height) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  width = png_get_image_width(png, info);
  height = png_get_image_height(png, info);
  return true;
}

// The conversions to RGBA8, set up once the size is accepted (libpng then sizes its row buffers).
bool convertToRgba8(png_structp png, png_infop info) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_expand(png);     // palette to RGB, grey below 8 bits to 8, tRNS to alpha
  png_set_strip_16(png);   // 16-bit samples to their high byte, row by row
  png_set_gray_to_rgb(png);
  png_set_add_alpha(png, 0xFF, PNG_FILLER_AFTER);  // opaque where the image has no alpha
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  return true;
}

bool readPixels(png_structp png, png_infop info, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, info);  // the rest of the file, to its IEND: a file cut after the pixels is cut all the same
  return true;
}

// libpng's read and info structs, destroyed together.
struct PngReader {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngReader() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

}  // namespace

bool isPng(std::string_view bytes) { return bytes.size() >= 8 && png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) == 0; }

TextureImage decodePng(std::string_view bytes, const std::string& what, const AcceptSize& accept) {
  PngStream stream{bytes};
  PngReader reader;
  reader.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &stream, onError, onWarning);
  if (reader.png) reader.info = png_create_info_struct(reader.png);
  if (!reader.info) throw std::bad_alloc();
  png_set_read_fn(reader.png, &stream, onRead);
  // The texture's own limit (accept) says what is too large, in its words, not libpng's default.
  png_set_user_limits(reader.png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
  png_uint_32 width = 0, height = 0;
  const auto fail = [&](const char* stage) {
    const std::string warning = *stream.warning ? std::string(" (") + stream.warning + ")" : "";
    throw SceneError(what + ": PNG: " + stage + ": " + stream.error + warning);
  };
  if (!readHeader(reader.png, reader.info, width, height)) fail("cannot read its header");
  accept(width, height);
  if (!convertToRgba8(reader.png, reader.info)) fail("cannot read its header");
  if (png_get_rowbytes(reader.png, reader.info) != size_t(width) * 4) throw SceneError(what + ": PNG: cannot convert its pixels to RGBA");
  TextureRows out = textureRows(width, height);
  if (!readPixels(reader.png, reader.info, out.rows.data())) fail("cannot decode its pixels");
  return std::move(out.texture);
}

}  // namespace phongvk
