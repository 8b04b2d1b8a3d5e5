// texture_decode_test.cpp — textures decoded by libpng and libjpeg-turbo (image/texture_decode.h):
// every legal kind of PNG and JPEG decodes to the right texels; every corrupt, truncated or
// unsupported one is an error in the codec's words, named PNG or JPEG from the file's signature,
// before any pixel past the damage is used; a header that asks for more than the memory limit is
// refused before its pixels are decoded. The images are made here by the codecs' own encoders and
// then damaged byte by byte where a case needs it.
#include "base/memory_limit.h"
#include "image/texture_decode.h"
#include "phongvk/errors.h"
#include "tests/test_util.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <jpeglib.h>

#include <csetjmp>
#include <string>
#include <vector>

namespace phongvk {
namespace {

// ---- making images ----

// A PNG of `width` x `height` pixels of the given type, every sample `value` (16-bit: value * 257).
std::string pngOf(uint32_t width, uint32_t height, int bitDepth, int colorType, int interlace = PNG_INTERLACE_NONE,
                  int value = 200) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_set_write_fn(png, &out, [](png_structp p, png_bytep data, size_t n) {
    static_cast<std::string*>(png_get_io_ptr(p))->append(reinterpret_cast<const char*>(data), n);
  }, nullptr);
  png_set_IHDR(png, info, width, height, bitDepth, colorType, interlace, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (colorType == PNG_COLOR_TYPE_PALETTE) {
    png_color palette[2] = {{10, 20, 30}, {40, 50, 60}};
    png_set_PLTE(png, info, palette, 2);
    png_byte alpha[1] = {128};
    png_set_tRNS(png, info, alpha, 1, nullptr);
  }
  png_write_info(png, info);
  const int channels = png_get_channels(png, info);
  std::vector<png_byte> row(size_t(width) * channels * (bitDepth == 16 ? 2 : 1) + 1, png_byte(value));
  if (colorType == PNG_COLOR_TYPE_PALETTE) std::fill(row.begin(), row.end(), png_byte(0));
  const int passes = png_set_interlace_handling(png);
  for (int pass = 0; pass < passes; ++pass) {
    for (uint32_t y = 0; y < height; ++y) png_write_row(png, row.data());
  }
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return out;
}

// A JPEG of `width` x `height` pixels, `components` 1 (grey) or 3, a smooth gradient.
std::string jpegOf(uint32_t width, uint32_t height, int components, bool progressive = false, bool arithmetic = false) {
  jpeg_compress_struct info;
  jpeg_error_mgr error;
  info.err = jpeg_std_error(&error);
  jpeg_create_compress(&info);
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&info, &buffer, &size);
  info.image_width = width;
  info.image_height = height;
  info.input_components = components;
  info.in_color_space = components == 1 ? JCS_GRAYSCALE : JCS_RGB;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, 90, TRUE);
  if (progressive) jpeg_simple_progression(&info);
  info.arith_code = arithmetic ? TRUE : FALSE;
  jpeg_start_compress(&info, TRUE);
  std::vector<JSAMPLE> row(size_t(width) * components);
  while (info.next_scanline < height) {
    for (size_t i = 0; i < row.size(); ++i) row[i] = JSAMPLE((i / components + info.next_scanline) * 255 / (width + height));
    JSAMPROW rows[1] = {row.data()};
    jpeg_write_scanlines(&info, rows, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  std::string out(reinterpret_cast<const char*>(buffer), size);
  std::free(buffer);
  return out;
}

uint32_t crc32Of(const std::string& bytes) {
  uint32_t crc = 0xFFFFFFFFu;
  for (unsigned char c : bytes) {
    crc ^= c;
    for (int k = 0; k < 8; ++k) crc = crc >> 1 ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

// `png` with the byte at `offset` into chunk `type`'s data set to `value`, its CRC made right again:
// only the decoder's own checks of the data can find the damage.
std::string pngPatched(std::string png, const std::string& type, size_t offset, uint8_t value) {
  const size_t at = png.find(type);
  const uint32_t length = uint32_t(uint8_t(png[at - 4])) << 24 | uint32_t(uint8_t(png[at - 3])) << 16 |
                          uint32_t(uint8_t(png[at - 2])) << 8 | uint8_t(png[at - 1]);
  png[at + 4 + offset] = char(value);
  const uint32_t crc = crc32Of(png.substr(at, 4 + length));
  for (int k = 0; k < 4; ++k) png[at + 4 + length + k] = char(crc >> (24 - 8 * k));
  return png;
}

// `jpeg` with the byte `offset` past its first SOF marker (0xFF `sof`) set to `value`.
std::string jpegPatched(std::string jpeg, uint8_t sof, size_t offset, uint8_t value) {
  const size_t at = jpeg.find(std::string("\xFF") + char(sof));
  jpeg[at + offset] = char(value);
  return jpeg;
}

std::string decodeError(const std::string& bytes) {
  return test::thrownMessage<SceneError>([&] { decodeTexture(bytes, "tex"); });
}

// ---- what decodes ----

TEST(TextureDecode, EveryKindOfPngDecodesToRgba8) {
  struct Case {
    int depth, type;
    uint32_t texel;
  } cases[] = {
      {8, PNG_COLOR_TYPE_RGB, 0xFFC8C8C8u},       {8, PNG_COLOR_TYPE_RGBA, 0xC8C8C8C8u},
      {8, PNG_COLOR_TYPE_GRAY, 0xFFC8C8C8u},      {8, PNG_COLOR_TYPE_GRAY_ALPHA, 0xC8C8C8C8u},
      {16, PNG_COLOR_TYPE_RGB, 0xFFC8C8C8u},      {16, PNG_COLOR_TYPE_RGBA, 0xC8C8C8C8u},  // the high byte of 200 * 257
      {8, PNG_COLOR_TYPE_PALETTE, 0x801E140Au},   // entry 0 with its tRNS alpha
  };
  for (const Case& c : cases) {
    for (int interlace : {PNG_INTERLACE_NONE, PNG_INTERLACE_ADAM7}) {
      const TextureImage t = decodeTexture(pngOf(13, 7, c.depth, c.type, interlace), "tex");
      ASSERT_EQ(t.width, 13u);
      ASSERT_EQ(t.height, 7u);
      for (uint32_t texel : t.texels) ASSERT_EQ(texel, c.texel) << c.depth << " " << c.type << " " << interlace;
    }
  }
}

TEST(TextureDecode, BaselineProgressiveArithmeticAndGreyJpegsDecode) {
  const TextureImage baseline = decodeTexture(jpegOf(40, 24, 3), "tex");
  for (bool progressive : {false, true}) {
    for (bool arithmetic : {false, true}) {
      const TextureImage t = decodeTexture(jpegOf(40, 24, 3, progressive, arithmetic), "tex");
      ASSERT_EQ(t.width, 40u);
      ASSERT_EQ(t.height, 24u);
      // The same coefficients, however they were coded: the same texels.
      EXPECT_EQ(std::vector<uint32_t>(t.texels.begin(), t.texels.end()),
                std::vector<uint32_t>(baseline.texels.begin(), baseline.texels.end())) << progressive << arithmetic;
    }
  }
  const TextureImage grey = decodeTexture(jpegOf(16, 16, 1), "tex");
  const uint32_t g = grey.texels[0] & 0xFF;
  EXPECT_EQ(grey.texels[0], 0xFF000000u | g << 16 | g << 8 | g);
}

// ---- what is refused, and why ----

TEST(TextureDecode, DamagedPngsSayWhatIsWrongInWords) {
  const std::string good = pngOf(8, 8, 8, PNG_COLOR_TYPE_RGB);
  EXPECT_EQ(decodeError(pngPatched(good, "IHDR", 8, 7)),
            "tex: PNG: cannot read its header: Invalid IHDR data (Invalid color type/bit depth combination in IHDR)");
  EXPECT_EQ(decodeError(pngPatched(good, "IHDR", 9, 5)),
            "tex: PNG: cannot read its header: Invalid IHDR data (Invalid color type in IHDR)");
  EXPECT_EQ(decodeError(pngPatched(pngPatched(good, "IHDR", 2, 0), "IHDR", 3, 0)),
            "tex: PNG: cannot read its header: Invalid IHDR data (Image width is zero in IHDR)");
  // A palette image without its PLTE chunk.
  std::string noPalette = pngOf(8, 8, 8, PNG_COLOR_TYPE_PALETTE);
  const size_t plte = noPalette.find("PLTE") - 4;
  noPalette.erase(plte, 12 + 6);  // length, type, 2 entries, CRC
  EXPECT_NE(decodeError(noPalette).find("tex: PNG: cannot read its header: "), std::string::npos) << decodeError(noPalette);
  // Compressed data that is not zlib's.
  const std::string badZlib = pngPatched(good, "IDAT", 0, 0x00);
  EXPECT_EQ(decodeError(badZlib).rfind("tex: PNG: cannot decode its pixels: IDAT: ", 0), 0u) << decodeError(badZlib);
  // Cut: before IEND, inside IDAT, after the signature.
  EXPECT_EQ(decodeError(good.substr(0, good.size() - 12)), "tex: PNG: cannot decode its pixels: the file ends early (truncated)");
  EXPECT_EQ(decodeError(good.substr(0, good.find("IDAT") + 10)), "tex: PNG: cannot decode its pixels: the file ends early (truncated)");
  EXPECT_EQ(decodeError(good.substr(0, 8)), "tex: PNG: cannot read its header: the file ends early (truncated)");
  // A header asking for sides a texture cannot have: refused before a pixel is decoded.
  for (uint32_t side : {65535u, 0x7FFFFFFFu}) {
    std::string huge = good;
    for (size_t offset : {0, 4}) {
      for (int k = 0; k < 4; ++k) huge = pngPatched(huge, "IHDR", offset + k, uint8_t(side >> (24 - 8 * k)));
    }
    EXPECT_EQ(decodeError(huge), "tex: the image is " + std::to_string(side) + "x" + std::to_string(side) +
                                     " pixels; a texture's sides are 1 to 16384");
  }
}

TEST(TextureDecode, DamagedAndUnsupportedJpegsSayWhatIsWrongInWords) {
  const std::string good = jpegOf(256, 256, 3);
  // Cut at 60% and closed with an EOI: the scan ends early, which libjpeg alone would fill with grey.
  const std::string cut = good.substr(0, good.size() * 6 / 10) + "\xFF\xD9";
  EXPECT_EQ(decodeError(cut), "tex: JPEG: cannot decode its pixels: Corrupt JPEG data: premature end of data segment");
  EXPECT_EQ(decodeError(good.substr(0, good.size() / 2)), "tex: JPEG: cannot decode its pixels: Premature end of JPEG file");
  // A 1 KB file whose header claims 16384 x 16384: the scan runs out at once.
  std::string claims = jpegOf(16, 16, 3);
  for (size_t offset : {5, 7}) claims = jpegPatched(jpegPatched(claims, 0xC0, offset, 0x40), 0xC0, offset + 1, 0x00);
  ASSERT_LT(claims.size(), 1024u);
  EXPECT_EQ(decodeError(claims), "tex: JPEG: cannot decode its pixels: Corrupt JPEG data: premature end of data segment");
  // Lossless (SOF3), 12-bit samples, no height.
  EXPECT_EQ(decodeError(jpegPatched(good, 0xC0, 1, 0xC3)), "tex: JPEG: cannot read its header: Unsupported JPEG process: SOF type 0xc3");
  EXPECT_EQ(decodeError(jpegPatched(good, 0xC0, 4, 12)), "tex: JPEG: cannot read its header: Unsupported JPEG data precision 12");
  EXPECT_EQ(decodeError(jpegPatched(jpegPatched(good, 0xC0, 5, 0), 0xC0, 6, 0)),
            "tex: JPEG: cannot read its header: Empty JPEG image (DNL not supported)");
  EXPECT_EQ(decodeError("\xFF\xD8\xFF"), "tex: JPEG: cannot read its header: Premature end of JPEG file");
}

TEST(TextureDecode, WhatIsNeitherPngNorJpegIsNamedByItsFirstBytes) {
  EXPECT_EQ(decodeError(""), "tex: not a PNG or JPEG image (it is empty)");
  EXPECT_EQ(decodeError("GIF89a"), "tex: not a PNG or JPEG image (it starts 47 49 46 38 39 61)");
  EXPECT_EQ(decodeError("\x89PNG"), "tex: not a PNG or JPEG image (it starts 89 50 4e 47)");
}

TEST(TextureDecode, TexturesPastTheMemoryLimitAreRefusedFromTheirHeaders) {
  setSceneMemoryLimit(uint64_t(1) << 20);  // 1 MiB: a 512 x 512 texture (1 MiB of texels) fits alone
  const std::string big = pngOf(512, 512, 8, PNG_COLOR_TYPE_RGB);
  const TextureImage first = decodeTexture(big, "first");
  const std::string refused = decodeError(big);
  setSceneMemoryLimit(0);
  EXPECT_EQ(refused.rfind("tex: a 512x512 texture needs about 0.00195 GiB ", 0), 0u) << refused;
  EXPECT_NE(refused.find("(1048576 bytes decoded, beside 1048576 bytes of textures held already)"), std::string::npos) << refused;
  EXPECT_NE(refused.find("smaller or fewer textures fit"), std::string::npos) << refused;
}

TEST(TextureDecode, APathWithANulIsRefusedNotCutShort) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/ok.png", pngOf(2, 2, 8, PNG_COLOR_TYPE_RGB));
  EXPECT_EQ(test::thrownMessage<SceneError>([&] { readTextureFile(dir + "/ok.png" + std::string(1, '\0') + ".evil", "tex"); }),
            "tex: cannot open '" + dir + "/ok.png\\0.evil': the path contains a NUL character");
}

}  // namespace
}  // namespace phongvk
