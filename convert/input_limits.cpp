#include "convert/input_limits.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/open_files.hpp"
#include "core/gzip.hpp"
#include "core/sha256.hpp"

namespace haptex::convert {

std::vector<char> read_whole_file(const std::string& path, std::uintmax_t max_bytes) {
  require_regular_file(path);
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw input_error(path, "", "cannot open the file (" + ec.message() + ")", "Check the path and permissions");
  if (size > max_bytes)
    throw input_error(path, "", "the file is " + std::to_string(size) + " bytes, over the limit of " +
                                    std::to_string(max_bytes) + " bytes",
                      "If the file is genuine, raise the limit with --max-bytes");
  std::vector<char> buffer(size);
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse_if_out_of_descriptors(errno, path);
  if (!in.read(buffer.data(), static_cast<std::streamsize>(size)))
    throw input_error(path, "", "the file could not be read completely", "Check the disk and permissions");
  return buffer;
}

InputFile read_input_file(const std::string& path, std::uintmax_t max_bytes) {
  std::vector<char> bytes = read_whole_file(path, max_bytes);
  if (gzip::is_gzip(bytes)) bytes = gzip::decompress(bytes, max_bytes, path);
  std::string sha = sha256_hex(bytes);
  return {std::move(bytes), std::move(sha)};
}

}  // namespace haptex::convert
