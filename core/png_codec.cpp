#include "core/png_codec.hpp"

#include <png.h>

#include <bit>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <new>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace wifislam {

namespace {

// libpng reports an error by calling the error function, which must not return: it jumps back to
// the setjmp of the libpng call that failed. The functions below that call setjmp (`write_rows`,
// `read_header`, `read_rows`) hold no object with a destructor, so the jump skips none, which is
// when C++ allows longjmp; everything that owns memory lives in their callers.

struct PngMessage {
  char text[256] = "";
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* m = static_cast<PngMessage*>(png_get_error_ptr(png));
  std::snprintf(m->text, sizeof m->text, "%s", message);
  png_longjmp(png, 1);
}

// Warnings (an ancillary chunk libpng finds odd, such as an sRGB profile) say nothing about the
// pixels; libpng's default would print them on stderr from the reader's thread.
void on_png_warning(png_structp, png_const_charp) {}

constexpr bool kLittleEndian = std::endian::native == std::endian::little;

// ---- writing -------------------------------------------------------------------------------

void append_to_vector(png_structp png, png_bytep data, std::size_t length) {
  auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
  try {
    out->insert(out->end(), data, data + length);
  } catch (const std::bad_alloc&) {
    png_error(png, "out of memory");
  }
}

void flush_nothing(png_structp) {}

/// OpenCV 4's PngEncoder::write with no parameters (modules/imgcodecs/src/grfmt_png.cpp): filter
/// SUB and zlib level 1 "for speed", strategy Z_RLE, BGR to RGB and 16-bit samples swapped to
/// big-endian by libpng, rows as they are.
bool write_rows(png_structp png, png_infop info, png_uint_32 width, png_uint_32 height,
                int bit_depth, int color_type, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_compression_level(png, 1);     // Z_BEST_SPEED
  png_set_compression_strategy(png, 3);  // Z_RLE
  png_set_IHDR(png, info, width, height, bit_depth, color_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_set_bgr(png);
  if (kLittleEndian) png_set_swap(png);
  png_write_image(png, rows);
  png_write_end(png, info);
  return true;
}

enum class PngDirection { kWrite, kRead };

/// Owns a libpng write or read struct and its info struct; `info()` is null when libpng could not
/// allocate them.
template <PngDirection kDirection>
class PngStruct {
 public:
  explicit PngStruct(PngMessage* message)
      : png_(kDirection == PngDirection::kWrite
                 ? png_create_write_struct(PNG_LIBPNG_VER_STRING, message, on_png_error,
                                           on_png_warning)
                 : png_create_read_struct(PNG_LIBPNG_VER_STRING, message, on_png_error,
                                          on_png_warning)) {
    if (png_ != nullptr) info_ = png_create_info_struct(png_);
  }
  ~PngStruct() {
    if constexpr (kDirection == PngDirection::kWrite) {
      png_destroy_write_struct(&png_, &info_);
    } else {
      png_destroy_read_struct(&png_, &info_, nullptr);
    }
  }
  PngStruct(const PngStruct&) = delete;
  PngStruct& operator=(const PngStruct&) = delete;
  png_structp png() const { return png_; }
  png_infop info() const { return info_; }

 private:
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
};

// ---- reading -------------------------------------------------------------------------------

struct MemoryInput {
  const unsigned char* data;
  std::size_t size;
  std::size_t offset;
};

void read_from_memory(png_structp png, png_bytep out, std::size_t length) {
  auto* in = static_cast<MemoryInput*>(png_get_io_ptr(png));
  if (length > in->size - in->offset) png_error(png, "the data end early (truncated)");
  std::memcpy(out, in->data + in->offset, length);
  in->offset += length;
}

struct PngHeader {
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, color_type = 0, transparent_entries = 0;
};

bool read_header(png_structp png, png_infop info, PngHeader* header) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  png_get_IHDR(png, info, &header->width, &header->height, &header->bit_depth, &header->color_type,
               nullptr, nullptr, nullptr);
  png_bytep alpha = nullptr;
  png_color_16p colour = nullptr;
  png_get_tRNS(png, info, &alpha, &header->transparent_entries, &colour);
  return true;
}

/// OpenCV 4's PngDecoder::readHeader: the type cv::imdecode gives with IMREAD_UNCHANGED.
int stored_type(const PngHeader& h) {
  int channels = 1;
  switch (h.color_type) {
    case PNG_COLOR_TYPE_RGB:
    case PNG_COLOR_TYPE_PALETTE:
      channels = h.transparent_entries > 0 ? 4 : 3;
      break;
    case PNG_COLOR_TYPE_GRAY_ALPHA:
    case PNG_COLOR_TYPE_RGB_ALPHA:
      channels = 4;
      break;
    default:
      channels = 1;
  }
  return CV_MAKETYPE(h.bit_depth == 16 ? CV_16U : CV_8U, channels);
}

/// OpenCV 4's PngDecoder::readData for an image read as stored (no 16 -> 8 bit strip): the same
/// libpng transformations in the same order.
bool read_rows(png_structp png, png_infop info, const PngHeader* header, int channels,
               png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  if (kLittleEndian) png_set_swap(png);
  if (channels < 4) {
    png_set_strip_alpha(png);
  } else {
    png_set_tRNS_to_alpha(png);
  }
  if (header->color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  const bool colour_stored = (header->color_type & PNG_COLOR_MASK_COLOR) != 0;
  if (!colour_stored && header->bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (colour_stored && channels > 1) {
    png_set_bgr(png);
  } else if (channels > 1) {
    png_set_gray_to_rgb(png);
  } else {
    png_set_rgb_to_gray(png, 1, 0.299, 0.587);
  }
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  return true;
}

// OpenCV's limits on a decoded image (CV_IO_MAX_IMAGE_WIDTH, _HEIGHT, _PIXELS): a header that
// claims more is refused before any allocation.
constexpr png_uint_32 kMaxSidePx = 1u << 20;
constexpr std::uint64_t kMaxPixels = std::uint64_t{1} << 30;

/// libpng takes rows as non-const pointers for reading and writing alike; when writing it copies
/// each row before transforming it (BGR order, byte swap), so the image is never changed.
std::vector<png_bytep> row_pointers(const cv::Mat& image) {
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.rows));
  for (int y = 0; y < image.rows; ++y) {
    rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(image.ptr(y));
  }
  return rows;
}

}  // namespace

std::vector<unsigned char> encode_png(const cv::Mat& image) {
  const int channels = image.channels();
  if ((image.depth() != CV_8U && image.depth() != CV_16U) ||
      (channels != 1 && channels != 3 && channels != 4) || image.empty()) {
    throw std::invalid_argument(
        fmt::format("encode_png: cannot write a {}x{} image of type {} as PNG (8 or 16 bits, 1, 3 "
                    "or 4 channels)",
                    image.cols, image.rows, image.type()));
  }
  PngMessage message;
  PngStruct<PngDirection::kWrite> png(&message);
  if (png.info() == nullptr) throw IoError("cannot encode a PNG image: libpng is out of memory");
  std::vector<unsigned char> bytes;
  png_set_write_fn(png.png(), &bytes, append_to_vector, flush_nothing);
  std::vector<png_bytep> rows = row_pointers(image);
  const int color_type = channels == 1   ? PNG_COLOR_TYPE_GRAY
                         : channels == 3 ? PNG_COLOR_TYPE_RGB
                                         : PNG_COLOR_TYPE_RGBA;
  if (!write_rows(png.png(), png.info(), static_cast<png_uint_32>(image.cols),
                  static_cast<png_uint_32>(image.rows), image.depth() == CV_8U ? 8 : 16, color_type,
                  rows.data())) {
    throw IoError(fmt::format("cannot encode a {}x{} image of type {} as PNG: {}", image.cols,
                              image.rows, image.type(), message.text));
  }
  return bytes;
}

cv::Mat decode_png(std::span<const unsigned char> bytes, const std::string& name) {
  if (bytes.empty()) throw ParseError(name, "", "the file is empty (0 bytes), not a PNG image");
  if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0) {
    throw ParseError(name, "",
                     "not a readable PNG image (it does not start with the PNG signature)");
  }
  PngMessage message;
  PngStruct<PngDirection::kRead> png(&message);
  if (png.info() == nullptr) throw IoError(name + ": cannot decode the PNG: out of memory");
  MemoryInput input{bytes.data(), bytes.size(), 0};
  png_set_read_fn(png.png(), &input, read_from_memory);
  const auto unreadable = [&] {
    return ParseError(
        name, "", fmt::format("not a readable PNG image (corrupt or truncated: {})", message.text));
  };
  PngHeader header;
  if (!read_header(png.png(), png.info(), &header)) throw unreadable();
  if (header.width > kMaxSidePx || header.height > kMaxSidePx ||
      std::uint64_t{header.width} * header.height > kMaxPixels) {
    throw ParseError(name, "",
                     fmt::format("a {}x{} PNG image is larger than this reader takes (2^20 pixels "
                                 "a side, 2^30 in all)",
                                 header.width, header.height));
  }
  cv::Mat image(static_cast<int>(header.height), static_cast<int>(header.width),
                stored_type(header));
  std::vector<png_bytep> rows = row_pointers(image);
  if (!read_rows(png.png(), png.info(), &header, image.channels(), rows.data())) {
    throw unreadable();
  }
  return image;
}

void write_png(const std::filesystem::path& path, const cv::Mat& image) {
  const std::vector<unsigned char> bytes = encode_png(image);
  write_file_atomic(path,
                    std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

cv::Mat read_png(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw ParseError(path.string(), "", "is a folder, not a PNG image");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path.string() + ": cannot open the image");
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  if (in.bad()) throw IoError(path.string() + ": read error");
  return decode_png(bytes, path.string());
}

}  // namespace wifislam
