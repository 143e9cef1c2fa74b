// core's PNG codec against OpenCV's imgcodecs, which it replaces: the bytes written are those of
// cv::imencode(".png") for every image type a dataset or a figure uses, and the pixels read are
// those of cv::imdecode(IMREAD_UNCHANGED) for PNGs of every colour type, bit depth and
// transparency OpenCV or libpng writes. Bad bytes are located errors.

#include <gtest/gtest.h>

#include <png.h>
#include <zlib.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/error.hpp"
#include "core/png_codec.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam {
namespace {

/// Pixels that compress badly (uniform noise) or well (gradients with flat runs), the two kinds a
/// rendered frame mixes.
cv::Mat test_image(int rows, int cols, int type, bool noisy, std::uint64_t seed) {
  cv::Mat image(rows, cols, type);
  if (noisy) {
    cv::RNG rng(seed);
    rng.fill(image, cv::RNG::UNIFORM, 0, CV_MAT_DEPTH(type) == CV_8U ? 256 : 65536);
    return image;
  }
  const int channels = image.channels();
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < cols; ++x) {
      for (int c = 0; c < channels; ++c) {
        const int value = (x / 4 + 3 * y + 40 * c) % 200;
        if (image.depth() == CV_8U) {
          image.ptr<std::uint8_t>(y)[x * channels + c] = static_cast<std::uint8_t>(value);
        } else {
          image.ptr<std::uint16_t>(y)[x * channels + c] = static_cast<std::uint16_t>(value * 300);
        }
      }
    }
  }
  return image;
}

bool same_pixels(const cv::Mat& a, const cv::Mat& b) {
  if (a.type() != b.type() || a.size() != b.size()) return false;
  for (int y = 0; y < a.rows; ++y) {
    if (std::memcmp(a.ptr(y), b.ptr(y), a.cols * a.elemSize()) != 0) return false;
  }
  return true;
}

std::vector<unsigned char> opencv_png(const cv::Mat& image, const std::vector<int>& params = {}) {
  std::vector<unsigned char> bytes;
  EXPECT_TRUE(cv::imencode(".png", image, bytes, params));
  return bytes;
}

TEST(PngCodec, WritesTheBytesOpenCvWritesForEveryTypeAndSize) {
  int checked = 0;
  std::uint64_t seed = 1;
  for (const int type : {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1, CV_16UC3, CV_16UC4}) {
    for (const cv::Size size : {cv::Size(1, 1), cv::Size(7, 5), cv::Size(640, 480)}) {
      for (const bool noisy : {true, false}) {
        SCOPED_TRACE(::testing::Message()
                     << "type " << type << ", " << size << ", noisy " << noisy);
        const cv::Mat image = test_image(size.height, size.width, type, noisy, ++seed);
        const std::vector<unsigned char> ours = encode_png(image);
        EXPECT_EQ(ours, opencv_png(image));
        // And it reads back as it was.
        EXPECT_TRUE(same_pixels(decode_png(ours, "ours"), image));
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 36);
}

TEST(PngCodec, WritesARegionOfALargerImageByItsRows) {
  const cv::Mat whole = test_image(60, 80, CV_8UC3, true, 7);
  const cv::Mat region = whole(cv::Rect(5, 3, 31, 17));
  ASSERT_FALSE(region.isContinuous());
  EXPECT_EQ(encode_png(region), opencv_png(region));
  EXPECT_TRUE(same_pixels(decode_png(encode_png(region), "region"), region.clone()));
}

TEST(PngCodec, RefusesTypesPngCannotHold) {
  EXPECT_THROW(encode_png(cv::Mat(4, 4, CV_32FC1, cv::Scalar(1.0))), std::invalid_argument);
  EXPECT_THROW(encode_png(cv::Mat(4, 4, CV_8UC2, cv::Scalar(1, 2))), std::invalid_argument);
  EXPECT_THROW(encode_png(cv::Mat()), std::invalid_argument);
}

/// PNGs OpenCV cannot write (palettes, transparency, grey with alpha, fewer than 8 bits), written
/// with libpng's simplified API.
std::vector<unsigned char> libpng_png(int width, int height, png_uint_32 format,
                                      const std::vector<std::uint8_t>& pixels,
                                      const std::vector<std::uint8_t>& colormap = {},
                                      int colormap_entries = 0) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = format;
  image.colormap_entries = static_cast<png_uint_32>(colormap_entries);
  png_alloc_size_t size = 0;
  const void* map = colormap.empty() ? nullptr : colormap.data();
  EXPECT_TRUE(png_image_write_get_memory_size(image, size, 0, pixels.data(), 0, map))
      << image.message;
  std::vector<unsigned char> bytes(size);
  EXPECT_TRUE(png_image_write_to_memory(&image, bytes.data(), &size, 0, pixels.data(), 0, map))
      << image.message;
  bytes.resize(size);
  return bytes;
}

std::vector<std::uint8_t> counting(std::size_t n, int modulo) {
  std::vector<std::uint8_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint8_t>((i * 37 + i / 5) % modulo);
  return v;
}

TEST(PngCodec, ReadsEveryColourTypeAsOpenCvReadsItUnchanged) {
  const int w = 13, h = 9;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  struct Case {
    std::string what;
    std::vector<unsigned char> png;
    int expected_type;
  };
  std::vector<Case> cases = {
      {"grey 8", opencv_png(test_image(h, w, CV_8UC1, true, 1)), CV_8UC1},
      {"colour 8", opencv_png(test_image(h, w, CV_8UC3, true, 2)), CV_8UC3},
      {"colour with alpha 8", opencv_png(test_image(h, w, CV_8UC4, true, 3)), CV_8UC4},
      {"grey 16", opencv_png(test_image(h, w, CV_16UC1, true, 4)), CV_16UC1},
      {"colour 16", opencv_png(test_image(h, w, CV_16UC3, true, 5)), CV_16UC3},
      {"colour with alpha 16", opencv_png(test_image(h, w, CV_16UC4, true, 6)), CV_16UC4},
      {"grey 1 bit",
       opencv_png(test_image(h, w, CV_8UC1, false, 7) > 100, {cv::IMWRITE_PNG_BILEVEL, 1}),
       CV_8UC1},
      {"grey, zlib level 9",
       opencv_png(test_image(h, w, CV_8UC1, false, 8), {cv::IMWRITE_PNG_COMPRESSION, 9}), CV_8UC1},
      {"grey with alpha", libpng_png(w, h, PNG_FORMAT_GA, counting(2 * n, 256)), CV_8UC4},
      {"grey with alpha 16", libpng_png(w, h, PNG_FORMAT_LINEAR_Y_ALPHA, counting(4 * n, 256)),
       CV_16UC4},
      {"palette",
       libpng_png(w, h, PNG_FORMAT_RGB_COLORMAP, counting(n, 40), counting(3 * 40, 256), 40),
       CV_8UC3},
      {"palette with transparency",
       libpng_png(w, h, PNG_FORMAT_RGBA_COLORMAP, counting(n, 40), counting(4 * 40, 256), 40),
       CV_8UC4},
      {"palette of 4 (2 bits a pixel)",
       libpng_png(w, h, PNG_FORMAT_RGB_COLORMAP, counting(n, 4), counting(3 * 4, 256), 4), CV_8UC3},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    const cv::Mat theirs = cv::imdecode(c.png, cv::IMREAD_UNCHANGED);
    const cv::Mat ours = decode_png(c.png, c.what);
    EXPECT_EQ(ours.type(), c.expected_type);
    EXPECT_EQ(theirs.type(), c.expected_type);
    EXPECT_TRUE(same_pixels(ours, theirs));
  }
}

void append_chunk(std::vector<unsigned char>& png, const char* type,
                  const std::vector<unsigned char>& data) {
  std::vector<unsigned char> chunk(type, type + 4);
  chunk.insert(chunk.end(), data.begin(), data.end());
  const auto append_u32 = [&png](std::uint32_t v) {
    for (const int shift : {24, 16, 8, 0}) png.push_back(static_cast<unsigned char>(v >> shift));
  };
  append_u32(static_cast<std::uint32_t>(data.size()));
  png.insert(png.end(), chunk.begin(), chunk.end());
  append_u32(static_cast<std::uint32_t>(crc32(0, chunk.data(), static_cast<uInt>(chunk.size()))));
}

/// PNG bytes with `width` x `height` in the header (8-bit grey), their CRCs right, and an empty
/// IDAT: a reader learns the size before any pixel.
std::vector<unsigned char> header_only_png(std::uint32_t width, std::uint32_t height) {
  std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<unsigned char> header;
  for (const std::uint32_t v : {width, height}) {
    for (const int shift : {24, 16, 8, 0}) header.push_back(static_cast<unsigned char>(v >> shift));
  }
  header.insert(header.end(), {8, 0, 0, 0, 0});  // 8-bit grey, no interlace
  append_chunk(png, "IHDR", header);
  append_chunk(png, "IDAT", {});
  return png;
}

std::string parse_error(const std::vector<unsigned char>& bytes) {
  try {
    decode_png(bytes, "frames/x.png");
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("frames/x.png"), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no ParseError";
  return {};
}

TEST(PngCodec, BadBytesAreLocatedErrorsNotImages) {
  EXPECT_NE(parse_error({}).find("0 bytes"), std::string::npos);
  const std::vector<unsigned char> jpeg_start = {0xff, 0xd8, 0xff, 0xe0, 0, 16, 'J', 'F', 'I', 'F'};
  EXPECT_NE(parse_error(jpeg_start).find("PNG signature"), std::string::npos);

  const std::vector<unsigned char> good = encode_png(test_image(48, 64, CV_8UC3, true, 9));
  for (const std::size_t keep :
       {std::size_t{8}, std::size_t{40}, good.size() / 2, good.size() - 1}) {
    SCOPED_TRACE(keep);
    const std::string e = parse_error(
        std::vector<unsigned char>(good.begin(), good.begin() + static_cast<long>(keep)));
    EXPECT_NE(e.find("not a readable PNG image"), std::string::npos) << e;
    EXPECT_TRUE(cv::imdecode(std::vector<unsigned char>(good.begin(),
                                                        good.begin() + static_cast<long>(keep)),
                             cv::IMREAD_UNCHANGED)
                    .empty())
        << "OpenCV reads what this reader refuses";
  }
  std::vector<unsigned char> flipped = good;
  flipped[good.size() / 2] ^= 0x40;  // inside the pixel data: the chunk's CRC no longer matches
  EXPECT_NE(parse_error(flipped).find("not a readable PNG image"), std::string::npos);

  // A header that claims 40000 x 40000 pixels (1.6 GB as 8-bit grey) is refused before any
  // allocation; libpng itself allows up to 10^6 a side.
  const std::string huge = parse_error(header_only_png(40000, 40000));
  EXPECT_NE(huge.find("40000x40000"), std::string::npos) << huge;
}

TEST(PngCodec, ReadsAFileAndNamesItWhenItCannot) {
  const std::filesystem::path dir = test::scratch_folder();
  const cv::Mat image = test_image(6, 5, CV_16UC1, true, 11);
  write_png(dir / "depth.png", image);
  EXPECT_TRUE(same_pixels(read_png(dir / "depth.png"), image));
  EXPECT_THROW(read_png(dir / "missing.png"), IoError);
  try {
    read_png(dir);
    FAIL() << "read a folder";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wifislam
