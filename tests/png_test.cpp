// png_test.cpp — PNG files at every level decode to the pixels they were given, by two decoders
// (stb_image through readPng, and libdeflate's strict inflate of the IDAT stream); the run-only
// coder's Huffman codes stay within deflate's limits; and FrameWriter writes every queued frame
// or reports the first failure.
#include "image/deflate_runs.h"
#include "phongvk/errors.h"
#include "tools/frame_writer.h"
#include "phongvk/image.h"
#include "phongvk/phongvk.h"
#include "test_util.h"

#include <libdeflate.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <set>

namespace phongvk {
namespace {

using test::makeTempDir;
using test::thrownMessage;

Image filled(int w, int h, const std::function<void(int, int, uint8_t*)>& pixel) {
  Image image(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) pixel(x, y, image.pixel(x, y));
  }
  return image;
}

Image noise(int w, int h, uint32_t seed) {
  std::mt19937 random(seed);
  return filled(w, h, [&](int, int, uint8_t* p) {
    for (int c = 0; c < 3; ++c) p[c] = uint8_t(random());
  });
}

// Smooth shading with flat stretches and steps, like a rendered frame.
Image shaded(int w, int h) {
  return filled(w, h, [&](int x, int y, uint8_t* p) {
    const bool inside = (x - w / 2) * (x - w / 2) + (y - h / 2) * (y - h / 2) < (w * h) / 8;
    p[0] = inside ? uint8_t(40 + x * 150 / w) : 20;
    p[1] = inside ? uint8_t(30 + y * 200 / h) : 20;
    p[2] = inside ? uint8_t((x + y) / 3) : 30;
  });
}

// A frame of the paper's scene at a small size, from the reference.
Image renderedFrame() {
  Renderer cpu(Backend::Cpu);
  return cpu.render(loadScene(test::sourcePath("scenes/paper/fig3_two_lights.json")).withImageSize(320, 213));
}

struct Chunk {
  std::string type;
  std::vector<uint8_t> data;
};

uint32_t bigEndian(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }

// The chunks of a PNG, each CRC checked.
std::vector<Chunk> chunks(const std::vector<uint8_t>& png) {
  const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  EXPECT_TRUE(png.size() >= 8 && std::equal(signature, signature + 8, png.begin()));
  std::vector<Chunk> out;
  for (size_t at = 8; at + 12 <= png.size();) {
    const uint32_t length = bigEndian(&png[at]);
    EXPECT_LE(at + 12 + length, png.size());
    if (at + 12 + length > png.size()) break;
    Chunk chunk{std::string(png.begin() + ptrdiff_t(at) + 4, png.begin() + ptrdiff_t(at) + 8),
                std::vector<uint8_t>(png.begin() + ptrdiff_t(at) + 8, png.begin() + ptrdiff_t(at + 8 + length))};
    EXPECT_EQ(bigEndian(&png[at + 8 + length]), uint32_t(libdeflate_crc32(0, &png[at + 4], length + 4))) << chunk.type;
    out.push_back(std::move(chunk));
    at += 12 + length;
  }
  return out;
}

// A PNG's header fields after the size (bit depth, colour type, compression, filter, interlace)
// and its pixel bytes as the file stores them, from its IDAT stream inflated by libdeflate (which
// rejects any stream that breaks RFC 1950/1951) and unfiltered ("Sub" on every row).
struct Decoded {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> header;
  std::vector<uint8_t> bytes;
};

Decoded inflatedBytes(const std::vector<uint8_t>& png) {
  Decoded out;
  std::vector<uint8_t> stream;
  for (const Chunk& chunk : chunks(png)) {
    if (chunk.type == "IHDR") {
      out.width = int(bigEndian(&chunk.data[0]));
      out.height = int(bigEndian(&chunk.data[4]));
      out.header.assign(chunk.data.begin() + 8, chunk.data.end());
    }
    if (chunk.type == "IDAT") stream.insert(stream.end(), chunk.data.begin(), chunk.data.end());
  }
  const std::map<std::vector<uint8_t>, size_t> bytesPerPixel = {{{8, 2, 0, 0, 0}, 3}, {{8, 6, 0, 0, 0}, 4}, {{16, 0, 0, 0, 0}, 2}, {{8, 0, 0, 0, 0}, 1}};
  EXPECT_EQ(bytesPerPixel.count(out.header), 1u) << "not a header phongvk writes";
  const size_t step = bytesPerPixel.count(out.header) ? bytesPerPixel.at(out.header) : 3;
  const size_t rowBytes = size_t(out.width) * step;
  std::vector<uint8_t> filtered((rowBytes + 1) * size_t(out.height));
  libdeflate_decompressor* inflater = libdeflate_alloc_decompressor();
  size_t got = 0;
  const auto result = libdeflate_zlib_decompress(inflater, stream.data(), stream.size(), filtered.data(), filtered.size(), &got);
  libdeflate_free_decompressor(inflater);
  EXPECT_EQ(result, LIBDEFLATE_SUCCESS);
  EXPECT_EQ(got, filtered.size());
  out.bytes.resize(rowBytes * size_t(out.height));
  for (size_t y = 0; y < size_t(out.height); ++y) {
    const uint8_t* row = &filtered[y * (rowBytes + 1)];
    EXPECT_EQ(row[0], 1) << "row " << y << " is not filtered Sub";
    uint8_t* pixels = out.bytes.data() + y * rowBytes;
    for (size_t i = 0; i < rowBytes; ++i) pixels[i] = uint8_t(row[1 + i] + (i >= step ? pixels[i - step] : 0));
  }
  return out;
}

Image inflated(const std::vector<uint8_t>& png) {
  Decoded decoded = inflatedBytes(png);
  EXPECT_EQ(decoded.header, (std::vector<uint8_t>{8, 2, 0, 0, 0}));
  Image image;
  image.width = decoded.width;
  image.height = decoded.height;
  image.rgb = std::move(decoded.bytes);
  return image;
}

void expectSamePixels(const Image& a, const Image& b, const std::string& what) {
  EXPECT_EQ(a.width, b.width) << what;
  EXPECT_EQ(a.height, b.height) << what;
  EXPECT_TRUE(a.rgb == b.rgb) << what;
}

TEST(Png, EveryLevelDecodesToTheSamePixelsByTwoDecoders) {
  const std::string dir = makeTempDir();
  const std::vector<std::pair<std::string, Image>> images = {
      {"1x1", noise(1, 1, 1)},
      {"one row", shaded(1000, 1)},
      {"one column", shaded(1, 700)},
      {"noise (no runs)", noise(97, 61, 2)},
      {"flat", filled(300, 200, [](int, int, uint8_t* p) { p[0] = 7, p[1] = 200, p[2] = 7; })},
      {"shaded", shaded(331, 257)},
      {"rows wider than deflate's window", shaded(11000, 3)},
      {"rendered", renderedFrame()},
  };
  for (const auto& [name, image] : images) {
    for (int level = PNG_LEVEL_MIN; level <= PNG_LEVEL_MAX; ++level) {
      const std::string what = name + " at level " + std::to_string(level);
      const std::vector<uint8_t> png = encodePng(image, level);
      expectSamePixels(inflated(png), image, what + " (libdeflate)");
      const std::string path = dir + "/out.png";
      writePng(path, image, level);
      expectSamePixels(readPng(path), image, what + " (stb_image)");
    }
  }
}

TEST(Png, SameImageSameBytesAndAnEncoderReusedAcrossSizesMatchesAFreshOne) {
  PngEncoder reused(PNG_LEVEL_RUNS);
  for (const Image& image : {shaded(200, 150), noise(31, 17, 3), shaded(640, 480), shaded(200, 150)}) {
    const std::vector<uint8_t> bytes = reused.encode(image);
    EXPECT_EQ(bytes, encodePng(image, PNG_LEVEL_RUNS));
    EXPECT_EQ(bytes, encodePng(image));  // the default level
  }
}

TEST(Png, RunsCompressARenderedFrameAndLevelsTradeSizeAsDocumented) {
  const Image frame = renderedFrame();
  const size_t stored = encodePng(frame, 0).size(), runs = encodePng(frame, 1).size();
  const size_t fast = encodePng(frame, 2).size(), smallest = encodePng(frame, 12).size();
  EXPECT_GT(stored, frame.rgb.size());  // stored: every byte, plus the filter bytes and framing
  EXPECT_LT(runs * 5, stored);
  EXPECT_LT(smallest, fast);
  EXPECT_LT(fast, runs);
}

TEST(Png, BadLevelAndMismatchedImageAreRejected) {
  EXPECT_EQ(thrownMessage<ArgumentError>([] { PngEncoder encoder(13); }),
            "PNG level 13 is out of range: 0 (no compression) to 12 (smallest files)");
  EXPECT_EQ(thrownMessage<ArgumentError>([] { encodePng(Image(), -1); }),
            "PNG level -1 is out of range: 0 (no compression) to 12 (smallest files)");
  Image broken(4, 4);
  broken.rgb.pop_back();
  EXPECT_EQ(thrownMessage<ArgumentError>([&] { encodePng(broken); }),
            "cannot encode a 4x4 image holding 47 bytes as PNG");
  const std::string dir = makeTempDir();
  EXPECT_EQ(thrownMessage<OutputError>([&] { writePng(dir + "/x.png", broken); }),
            "cannot write '" + dir + "/x.png': cannot encode a 4x4 image holding 47 bytes as PNG");
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
}

// An RGBA image: the RGB image's colours, and alpha 0 and 255 in blocks with a ramp between.
ImageRGBA withAlpha(const Image& rgb) {
  ImageRGBA image{rgb.width, rgb.height, std::vector<uint8_t>(size_t(rgb.width) * rgb.height * 4)};
  for (size_t i = 0; i < size_t(rgb.width) * rgb.height; ++i) {
    std::copy_n(&rgb.rgb[i * 3], 3, &image.rgba[i * 4]);
    const size_t x = i % size_t(rgb.width);
    image.rgba[i * 4 + 3] = x < 10 ? 0 : x < 20 ? uint8_t(x * 12) : 255;
  }
  return image;
}

// 16-bit samples whose high and low bytes both change: a depth ramp in millimetres, a flat run of
// empty pixels (0), the largest value and noise.
ImageGrey16 grey16(int w, int h, uint32_t seed) {
  std::mt19937 random(seed);
  ImageGrey16 image{w, h, std::vector<uint16_t>(size_t(w) * h)};
  for (size_t i = 0; i < image.grey.size(); ++i) {
    const size_t x = i % size_t(w);
    image.grey[i] = x < 5 ? 0 : x == 5 ? 65535 : x < size_t(w) / 2 ? uint16_t(700 + 37 * x) : uint16_t(random());
  }
  return image;
}

std::vector<uint8_t> bigEndianBytes(const ImageGrey16& image) {
  std::vector<uint8_t> bytes;
  for (uint16_t v : image.grey) bytes.insert(bytes.end(), {uint8_t(v >> 8), uint8_t(v)});
  return bytes;
}

TEST(Png, RgbaAndGrey16DecodeToTheSamePixelsAtEveryLevelByTwoDecoders) {
  const std::string dir = makeTempDir(), path = dir + "/out.png";
  for (const ImageRGBA& image : {withAlpha(noise(1, 1, 4)), withAlpha(shaded(331, 257)), withAlpha(noise(97, 61, 5))}) {
    for (int level = PNG_LEVEL_MIN; level <= PNG_LEVEL_MAX; ++level) {
      const Decoded decoded = inflatedBytes(encodePng(image, level));
      EXPECT_EQ(decoded.header, (std::vector<uint8_t>{8, 6, 0, 0, 0}));  // 8 bits, colour type 6
      EXPECT_EQ(decoded.width, image.width);
      EXPECT_TRUE(decoded.bytes == image.rgba) << "RGBA at level " << level;
      writePng(path, image, level);
      EXPECT_TRUE(readPngRGBA(path).rgba == image.rgba) << "RGBA at level " << level << " (stb_image)";
    }
  }
  for (const ImageGrey16& image : {grey16(1, 1, 6), grey16(300, 7, 7), grey16(11000, 2, 8)}) {
    for (int level = PNG_LEVEL_MIN; level <= PNG_LEVEL_MAX; ++level) {
      const Decoded decoded = inflatedBytes(encodePng(image, level));
      EXPECT_EQ(decoded.header, (std::vector<uint8_t>{16, 0, 0, 0, 0}));  // 16 bits, grey
      EXPECT_EQ(decoded.height, image.height);
      EXPECT_TRUE(decoded.bytes == bigEndianBytes(image)) << "grey16 at level " << level;
      writePng(path, image, level);
      const ImageGrey16 read = readPngGrey16(path);
      EXPECT_EQ(read.width, image.width);
      EXPECT_TRUE(read.grey == image.grey) << "grey16 at level " << level << " (stb_image)";
    }
  }
}

TEST(Png, Grey8IsEightBitGreyThatReadsBackScaledBy257) {
  const std::string dir = makeTempDir(), path = dir + "/grey8.png";
  ImageGrey8 image{13, 5, {}};
  for (int i = 0; i < 13 * 5; ++i) image.grey.push_back(uint8_t(i * 37));
  for (int level = PNG_LEVEL_MIN; level <= PNG_LEVEL_MAX; ++level) {
    const Decoded decoded = inflatedBytes(encodePng(image, level));
    EXPECT_EQ(decoded.header, (std::vector<uint8_t>{8, 0, 0, 0, 0}));  // 8 bits, grey
    EXPECT_TRUE(decoded.bytes == image.grey) << "grey8 at level " << level;
  }
  writePng(path, image);
  const ImageGrey16 read = readPngGrey16(path);
  ASSERT_EQ(read.grey.size(), image.grey.size());
  for (size_t i = 0; i < read.grey.size(); ++i) EXPECT_EQ(read.grey[i], image.grey[i] * 257) << i;
  EXPECT_THROW(encodePng(ImageGrey8{4, 4, std::vector<uint8_t>(15)}), ArgumentError);
}

TEST(Png, AnRgbFileReadAsRgbaIsOpaqueAndMismatchedImagesAreRejected) {
  const std::string dir = makeTempDir();
  const Image rgb = shaded(40, 30);
  writePng(dir + "/rgb.png", rgb);
  const ImageRGBA rgba = readPngRGBA(dir + "/rgb.png");
  ASSERT_EQ(rgba.rgba.size(), rgb.rgb.size() / 3 * 4);
  EXPECT_EQ(rgba.rgba[3], 255);
  EXPECT_EQ(rgba.rgba[4], rgb.rgb[3]);
  EXPECT_EQ(thrownMessage<ArgumentError>([] { encodePng(ImageRGBA{2, 2, std::vector<uint8_t>(12)}); }),
            "cannot encode a 2x2 image holding 12 bytes as PNG");
  EXPECT_EQ(thrownMessage<OutputError>([&] { writePng(dir + "/x.png", ImageGrey16{2, 3, std::vector<uint16_t>(5)}); }),
            "cannot write '" + dir + "/x.png': cannot encode a 2x3 image holding 5 samples as PNG");
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
}

// Sum over codes of 2^-length: exactly 1 for a complete prefix code.
double kraftSum(const std::vector<uint8_t>& lengths) {
  double sum = 0;
  for (uint8_t length : lengths) {
    if (length != 0) sum += std::ldexp(1.0, -length);
  }
  return sum;
}

TEST(DeflateRuns, HuffmanLengthsAreCompleteWithinTheLimitAndDeterministic) {
  // Fibonacci frequencies make the unlimited code 40 levels deep.
  std::vector<uint32_t> fibonacci(40);
  fibonacci[0] = fibonacci[1] = 1;
  for (size_t i = 2; i < fibonacci.size(); ++i) fibonacci[i] = fibonacci[i - 1] + fibonacci[i - 2];
  std::mt19937 random(5);
  std::vector<uint32_t> skewed(286);
  for (uint32_t& f : skewed) f = (random() % 4 == 0) ? 0 : uint32_t(1) << (random() % 24);
  for (const auto& [frequencies, limit] : {std::pair{fibonacci, 15}, std::pair{fibonacci, 7}, std::pair{skewed, 15}}) {
    const std::vector<uint8_t> lengths = huffmanLengths(frequencies, limit);
    EXPECT_DOUBLE_EQ(kraftSum(lengths), 1.0);
    EXPECT_LE(*std::max_element(lengths.begin(), lengths.end()), limit);
    for (size_t s = 0; s < frequencies.size(); ++s) EXPECT_EQ(lengths[s] != 0, frequencies[s] != 0) << s;
    EXPECT_EQ(lengths, huffmanLengths(frequencies, limit));
  }
  // Fewer than two symbols still make a complete code of two (an inflater rejects less).
  for (const std::vector<uint32_t>& few : {std::vector<uint32_t>(19, 0), std::vector<uint32_t>{0, 0, 9, 0}}) {
    const std::vector<uint8_t> lengths = huffmanLengths(few, 7);
    EXPECT_EQ(std::count(lengths.begin(), lengths.end(), 1), 2);
    EXPECT_DOUBLE_EQ(kraftSum(lengths), 1.0);
  }
}

TEST(FrameWriter, WritesEveryFrameWithSpareImagesToReuse) {
  const std::string dir = makeTempDir();
  std::set<int> reported;
  {
    FrameWriter writer(3, 2, PNG_LEVEL_RUNS, [&](const FrameFile& frame) { reported.insert(frame.index); });
    for (int i = 0; i < 20; ++i) {
      Image image = writer.spareImage();
      image = shaded(64 + i, 48);
      writer.push({i, dir + "/f" + std::to_string(i) + ".png", std::move(image)});
    }
    writer.finish();
    EXPECT_EQ(reported.size(), 20u);
    EXPECT_GT(writer.spareImage().rgb.capacity(), 0u);
  }
  for (int i = 0; i < 20; ++i) expectSamePixels(readPng(dir + "/f" + std::to_string(i) + ".png"), shaded(64 + i, 48), "frame");
}

TEST(FrameWriter, AFailedWriteIsRethrownNamingTheFileAndStopsTheRest) {
  const std::string dir = makeTempDir();
  FrameWriter writer(2, 2, PNG_LEVEL_RUNS);
  const std::string missing = dir + "/no such folder/f.png";
  writer.push({0, missing, shaded(32, 32)});
  const std::string message = thrownMessage<OutputError>([&] {
    for (int i = 1; i < 1000; ++i) writer.push({i, dir + "/f" + std::to_string(i) + ".png", shaded(32, 32)});
    writer.finish();
  });
  EXPECT_EQ(message, "cannot write '" + missing + "': folder '" + std::filesystem::path(missing).parent_path().string() + "' does not exist");
  EXPECT_EQ(thrownMessage<OutputError>([&] { writer.finish(); }), message);
}

TEST(FrameWriter, DestroyedWithFramesQueuedWritesThemFirst) {
  const std::string dir = makeTempDir();
  {
    FrameWriter writer(1, 8, 6);
    for (int i = 0; i < 8; ++i) writer.push({i, dir + "/f" + std::to_string(i) + ".png", shaded(100, 80)});
  }
  for (int i = 0; i < 8; ++i) EXPECT_TRUE(std::filesystem::exists(dir + "/f" + std::to_string(i) + ".png")) << i;
}

TEST(FrameWriter, BadLevelThrowsBeforeAnyThreadStarts) {
  EXPECT_THROW(FrameWriter(2, 2, 99), ArgumentError);
}

}  // namespace
}  // namespace phongvk
