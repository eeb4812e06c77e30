#pragma once
// A CSV file of numbers with one header row, as rigs and databases log them: the columns a reader
// asks for, parsed, every bad cell refused naming its line and column (docs/convert.md).
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace haptex::convert {

struct CsvTable {
  std::vector<std::string> header;                     // as written, without quotes and white space
  std::map<std::string, std::vector<double>> columns;  // the kept columns, by header name
  std::map<std::string, std::vector<std::size_t>> lines;  // each value's line number (1: the header)
  std::string sha256;                                  // of the file's bytes
};

// Reads `path` (refused over max_bytes), keeping the columns whose header name `keep` accepts; in
// columns `sparse` accepts, an empty cell is no sample (a channel logged slower than the others).
// Throws haptex::Error (bad_input) for an empty file, a kept column named twice, a blank line
// between rows (only the end may hold them), a row with another number of fields than the header,
// and a kept cell that is not a number parse_stored_number takes.
CsvTable read_csv_table(const std::string& path, std::uintmax_t max_bytes,
                        const std::function<bool(const std::string&)>& keep,
                        const std::function<bool(const std::string&)>& sparse = {});

}  // namespace haptex::convert
