#include "core/gzip.hpp"

#include <zlib.h>

#include <algorithm>
#include <limits>

#include "core/error.hpp"

namespace haptex::gzip {
namespace {

constexpr int kGzipWindow = 15 + 16;  // zlib's window bits, + 16: a gzip header and trailer
constexpr std::size_t kStep = std::size_t(1) << 20;

// zlib counts in uInt: feed and drain in pieces it can hold.
uInt piece(std::size_t n) { return uInt(std::min<std::size_t>(n, std::numeric_limits<uInt>::max())); }

}  // namespace

bool is_gzip(std::span<const char> bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f && static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::string compress(std::string_view text, int level) {
  z_stream z{};
  if (deflateInit2(&z, level, Z_DEFLATED, kGzipWindow, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw failure("gzip: zlib cannot start compressing");
  std::string out(deflateBound(&z, uLong(text.size())) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  std::size_t in_left = text.size();
  int status = Z_OK;
  while (status != Z_STREAM_END) {
    z.avail_in = piece(in_left);
    const uInt fed = z.avail_in;
    if (std::size_t(z.total_out) == out.size()) out.resize(out.size() + kStep);
    z.next_out = reinterpret_cast<Bytef*>(out.data() + z.total_out);
    z.avail_out = piece(out.size() - std::size_t(z.total_out));
    status = deflate(&z, in_left == fed ? Z_FINISH : Z_NO_FLUSH);
    in_left -= fed - z.avail_in;
    if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR) {
      deflateEnd(&z);
      throw failure("gzip: zlib failed while compressing");
    }
  }
  out.resize(std::size_t(z.total_out));
  deflateEnd(&z);
  return out;
}

std::vector<char> decompress(std::span<const char> compressed, std::uintmax_t max_bytes, const std::string& source) {
  z_stream z{};
  if (inflateInit2(&z, kGzipWindow) != Z_OK) throw failure("gzip: zlib cannot start decompressing");
  std::vector<char> out;
  std::size_t used = 0;  // bytes of `compressed` taken by the members already finished
  // One byte over the limit tells a file that exceeds it.
  const std::uintmax_t room = max_bytes == std::numeric_limits<std::uintmax_t>::max() ? max_bytes : max_bytes + 1;
  const auto fail = [&](const std::string& where, const std::string& what, const std::string& fix) {
    inflateEnd(&z);
    return input_error(source, where, what, fix);
  };
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
  while (true) {
    z.avail_in = piece(compressed.size() - used - std::size_t(z.total_in));
    if (out.size() == std::size_t(z.total_out))
      out.resize(std::size_t(std::min<std::uintmax_t>(room, std::max<std::uintmax_t>(kStep, 2 * out.size()))));
    z.next_out = reinterpret_cast<Bytef*>(out.data() + z.total_out);
    z.avail_out = piece(out.size() - std::size_t(z.total_out));
    const int status = inflate(&z, Z_NO_FLUSH);
    if (std::uintmax_t(z.total_out) > max_bytes)
      throw fail("", "the file decompresses to more than the limit of " + std::to_string(max_bytes) + " bytes",
                 "If the file is genuine, raise the limit with --max-bytes");
    const std::size_t at = used + std::size_t(z.total_in);
    if (status == Z_OK) continue;
    if (status == Z_STREAM_END) {
      if (at == compressed.size()) break;
      // Another member may follow (what `cat a.gz b.gz` makes); anything else is refused.
      if (!is_gzip(compressed.subspan(at)))
        throw fail("byte " + std::to_string(at), "bytes that are not gzip data follow the compressed data",
                   "Compress the file again with gzip");
      const uLong kept = z.total_out;  // inflateReset clears the counts; the output goes on where it stopped
      inflateReset(&z);
      z.total_out = kept;
      used = at;
      z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data() + used));
      continue;
    }
    const std::string fix = "The gzip file is damaged or cut short; copy or compress it again";
    if (status == Z_BUF_ERROR && z.avail_in == 0)
      throw fail("byte " + std::to_string(at), "the gzip data ends before its end mark (the file is cut short)", fix);
    throw fail("byte " + std::to_string(at), std::string("the gzip data is damaged (") + (z.msg ? z.msg : "zlib error") + ")", fix);
  }
  out.resize(std::size_t(z.total_out));
  inflateEnd(&z);
  return out;
}

}  // namespace haptex::gzip
