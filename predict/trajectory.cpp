#include "predict/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "core/text/parse_number.hpp"
#include "core/text/utf8.hpp"
#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "dataset/window.hpp"

namespace haptex::predict {

using text::describe_bad_number, text::parse_stored_number;
namespace {

constexpr double kSamplePeriod = 1e-4;  // 10 kHz

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) {
    while (!field.empty() && (field.back() == '\r' || field.back() == ' ')) field.pop_back();
    while (!field.empty() && field.front() == ' ') field.erase(field.begin());
    out.push_back(field);
  }
  return out;
}

// The one column named by any of `names`; two such columns are refused (which would be meant?).
int column(const std::string& path, const std::vector<std::string>& header, std::initializer_list<const char*> names) {
  int found = -1;
  for (std::size_t i = 0; i < header.size(); ++i)
    for (const char* n : names)
      if (header[i] == n) {
        if (found >= 0)
          throw input_error(path, "line 1", "columns " + std::to_string(found + 1) + " and " + std::to_string(i + 1) + " are both " +
                                                header[std::size_t(found)] + (header[std::size_t(found)] == header[i] ? "" : " and " + header[i]),
                            "Keep one of them");
        found = int(i);
      }
  return found;
}

// The next line (without its newline) of at most kLongestLine bytes; false at the end of the file. A
// longer one (a file of zeros, a binary file) is refused as soon as it is seen, not read whole into
// memory first (review 14, F2).
constexpr std::size_t kLongestLine = 4096;  // a row of three numbers is far shorter
bool next_line(std::istream& in, std::string& line, const std::string& path, std::size_t number) {
  line.clear();
  for (int c; (c = in.get()) != std::char_traits<char>::eof();) {
    if (c == '\n') return true;
    if (line.size() == kLongestLine)
      throw input_error(path, "line " + std::to_string(number), "is longer than " + std::to_string(kLongestLine) + " bytes: this is no trajectory CSV",
                        "Give one sample per line: time_s,force,speed");
    line.push_back(char(c));
  }
  return !line.empty();
}

}  // namespace

Trajectory read_trajectory(const std::string& path) {
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw input_error(path, "", "cannot open the trajectory", "Check the path");
  std::string line;
  if (!next_line(in, line, path, 1)) throw input_error(path, "line 1", "the file is empty", "Write a header: time_s,force,speed");
  // A spreadsheet's CSV may start with a UTF-8 byte order mark and quote its column names (review 5
  // and 6: "the header names no force or no speed column").
  std::vector<std::string> header = fields(std::string(text::without_byte_order_mark(line)));
  for (std::string& name : header)
    if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
  const int f = column(path, header, {"force", "force_n"}), s = column(path, header, {"speed", "speed_mm_s"}),
            t = column(path, header, {"time_s"});
  if (f < 0 || s < 0)
    throw input_error(path, "line 1", "the header names no force or no speed column", "Name the columns force (N) and speed (mm/s)");
  Trajectory out;
  double previous_time = NAN;
  std::size_t blank = 0;  // the first blank line, while only blank lines follow it
  for (std::size_t number = 2; next_line(in, line, path, number); ++number) {
    if (line.empty() || line == "\r") {
      if (!blank) blank = number;
      continue;
    }
    // Each row is the next 0.1 ms: a blank one among them would shift every later sample (review 5).
    if (blank)
      throw input_error(path, "line " + std::to_string(blank), "is blank, among the samples (each row is the next 0.1 ms)",
                        "Remove the blank line, or give the sample it stands for");
    const std::string where = "line " + std::to_string(number);
    // Counted before split: a line of 80 million empty fields took 4.5 GB as pieces (review 10, F3).
    if (const std::size_t count = std::size_t(std::count(line.begin(), line.end(), ',')) + 1; count > header.size())
      throw input_error(path, where, "has " + std::to_string(count) + " fields but the header names " + std::to_string(header.size()),
                        "Give each row one value per header column");
    const std::vector<std::string> v = fields(line);
    auto value = [&](int c, const char* what) {
      if (std::size_t(c) >= v.size()) throw input_error(path, where, std::string("the ") + what + " column is missing", "Fix or remove the line");
      const std::optional<double> x = parse_stored_number(v[std::size_t(c)]);
      if (!x)
        throw input_error(path, where + ", column " + what, describe_bad_number(v[std::size_t(c)]),
                          "Fix or remove the line");
      return *x;
    };
    const double force = value(f, "force"), speed = value(s, "speed");
    if (force < 0 || speed < 0) throw input_error(path, where, "negative force or speed", "Give magnitudes: force in N, speed in mm/s");
    if (t >= 0) {
      const double time = value(t, "time_s");
      if (!std::isnan(previous_time) && std::abs(time - previous_time - kSamplePeriod) > 0.01 * kSamplePeriod)
        throw input_error(path, where, "time_s does not step by 0.1 ms", "Resample the trajectory to 10 kHz");
      previous_time = time;
    }
    out.force.push_back(float(force));
    out.speed.push_back(float(speed));
  }
  if (out.force.empty()) throw input_error(path, "line 2", "no samples", "Add one row per 0.1 ms");
  return out;
}

std::string trajectory_csv_text(const Trajectory& trajectory) {
  std::string text = std::string(kTrajectoryCsvHeader) + "\n";
  char row[96];
  for (std::size_t i = 0; i < trajectory.force.size(); ++i) {
    const int n = std::snprintf(row, sizeof row, "%.4f,%.9g,%.9g\n", double(i) * kSamplePeriod, double(trajectory.force[i]),
                                double(trajectory.speed[i]));
    text.append(row, std::size_t(n));
  }
  return text;
}

bool is_trajectory_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string expected = std::string(kTrajectoryCsvHeader) + "\n";
  std::string first(expected.size(), '\0');
  return in.read(first.data(), std::streamsize(first.size())) && first == expected;
}

void action_at(const Trajectory& trajectory, std::size_t t, float* out) {
  dataset::action_ending_at<float>(trajectory.force, trajectory.speed, t, std::span(out, dataset::kActionValues));
}

void check_trajectory_csv_output(const std::string& path, bool overwrite) {
  check_replaceable_output(path, overwrite, std::string("a trajectory CSV haptex wrote (its first line ") + kTrajectoryCsvHeader + ")",
                           is_trajectory_csv);
}

}  // namespace haptex::predict
