// jpeg_decode.cpp — decodeJpeg (texture_codecs.h) with libjpeg-turbo. libjpeg reports errors by
// calling error_exit, which must not return: it longjmps, so the calls that may jump sit in small
// functions with nothing to destroy, and the message is thrown from ordinary C++ afterwards.
// Corrupt data and an early end are warnings to libjpeg (it fills the rest with grey); here they
// are errors.
#include "image/texture_codecs.h"

#include "phongvk/errors.h"

#include <cstdio>  // libjpeg's header needs FILE and size_t first
#include <jpeglib.h>
#include <jerror.h>  // after libjpeg's header: the message codes (JWRN_*)

#include <csetjmp>
#include <utility>
#include <vector>

namespace phongvk {

namespace {

struct JpegError {
  jpeg_error_mgr manager;  // first: libjpeg's err pointer is this struct's address
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX] = "";
};

[[noreturn]] void onError(j_common_ptr info) {
  auto* error = reinterpret_cast<JpegError*>(info->err);
  (*info->err->format_message)(info, error->message);
  std::longjmp(error->jump, 1);
}

// Warnings that leave the pixels right (an unknown JFIF revision, a bad ICC profile
// size, an odd Adobe transform flag) pass; every other warning is corrupt or missing data.
void onMessage(j_common_ptr info, int level) {
  if (level >= 0) return;  // trace messages
  switch (info->err->msg_code) {
    case JWRN_JFIF_MAJOR:
    case JWRN_ADOBE_XFORM:
    case JWRN_BOGUS_ICC:
      return;
    default:
      onError(info);
  }
}

// The header, and the decoder started for RGBA8 (CMYK as it is); false with JpegError::message set.
bool startDecoding(jpeg_decompress_struct& info, JpegError& error, std::string_view bytes, bool& cmyk) {
  if (setjmp(error.jump)) return false;
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&info, TRUE);
  cmyk = info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK;
  info.out_color_space = cmyk ? JCS_CMYK : JCS_EXT_RGBA;
  info.dct_method = JDCT_ISLOW;  // exact integer IDCT: the same texels with or without SIMD
  jpeg_calc_output_dimensions(&info);
  return true;
}

bool decodeRows(jpeg_decompress_struct& info, JpegError& error, JSAMPARRAY rows) {
  if (setjmp(error.jump)) return false;
  jpeg_start_decompress(&info);
  while (info.output_scanline < info.output_height) jpeg_read_scanlines(&info, rows + info.output_scanline, info.output_height - info.output_scanline);
  jpeg_finish_decompress(&info);
  return true;
}

// Adobe's CMYK JPEGs store inverted inks: red = C·K / 255, as stb_image and browsers read them.
void cmykToRgba(Texels& texels) {
  for (uint32_t& texel : texels) {
    const uint32_t c = texel & 0xFF, m = texel >> 8 & 0xFF, y = texel >> 16 & 0xFF, k = texel >> 24;
    const auto ink = [k](uint32_t v) { return (v * k + 127) / 255; };
    texel = ink(c) | ink(m) << 8 | ink(y) << 16 | 0xFF000000u;
  }
}

// Destroyed whether or not jpeg_create_decompress ran: a zeroed struct holds nothing to free.
struct JpegReader {
  jpeg_decompress_struct info{};
  ~JpegReader() { jpeg_destroy_decompress(&info); }
};

}  // namespace

bool isJpeg(std::string_view bytes) {
  return bytes.size() >= 3 && uint8_t(bytes[0]) == 0xFF && uint8_t(bytes[1]) == 0xD8 && uint8_t(bytes[2]) == 0xFF;
}

TextureImage decodeJpeg(std::string_view bytes, const std::string& what, const AcceptSize& accept) {
  JpegError error;
  JpegReader reader;
  reader.info.err = jpeg_std_error(&error.manager);
  error.manager.error_exit = onError;
  error.manager.emit_message = onMessage;
  const auto fail = [&](const char* stage) { throw SceneError(what + ": JPEG: " + stage + ": " + error.message); };
  bool cmyk = false;
  if (!startDecoding(reader.info, error, bytes, cmyk)) fail("cannot read its header");
  const uint32_t width = reader.info.output_width, height = reader.info.output_height;
  accept(width, height);
  TextureRows out = textureRows(width, height);
  if (!decodeRows(reader.info, error, out.rows.data())) fail("cannot decode its pixels");
  if (cmyk) cmykToRgba(out.texture.texels);
  return std::move(out.texture);
}

}  // namespace phongvk
