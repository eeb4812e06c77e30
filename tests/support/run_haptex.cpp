#include "tests/support/run_haptex.hpp"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>

#include "core/process/run_program.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {

static std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

static CommandResult run(const std::vector<std::string>& argv, const std::string& directory, const std::string& input) {
  TempDir dir;
  const std::string out = dir.file("out"), err = dir.file("err");
  CommandResult result;
  result.exit_code = process::run_program({argv, directory, out, err, input, {}});
  result.out = slurp(out);
  result.err = slurp(err);
  return result;
}

CommandResult run_program(const std::vector<std::string>& argv, const std::string& directory) { return run(argv, directory, ""); }

std::string haptex_binary() {
  const char* other = std::getenv("HAPTEX_TEST_BINARY");
  return other && *other ? other : HAPTEX_BINARY;
}

CommandResult run_haptex_in(const std::string& directory, const std::vector<std::string>& args) {
  std::vector<std::string> argv{haptex_binary()};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_program(argv, directory);
}

CommandResult run_haptex(const std::vector<std::string>& args) { return run_haptex_in("", args); }

CommandResult run_haptex_fed(const std::vector<std::string>& args, const std::string& input) {
  std::vector<std::string> argv{haptex_binary()};
  argv.insert(argv.end(), args.begin(), args.end());
  return run(argv, "", input);
}

CommandResult run_python(const std::vector<std::string>& args) {
  std::vector<std::string> argv{"/usr/bin/python3"};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_program(argv);
}

bool python_has(const std::string& modules) { return run_python({"-c", "import " + modules}).exit_code == 0; }

namespace {

bool is_progress_line(const std::string& line) {
  static const std::regex progress(R"([a-z ]+: [0-9]+/[0-9]+ [^\r\x1b]*\([0-9]+ s\))");
  return std::regex_match(line, progress);
}

}  // namespace

bool only_progress_lines(const std::string& err) {
  return without_progress_lines(err).empty() && (err.empty() || err.back() == '\n');
}

std::string without_progress_lines(const std::string& err) {
  std::istringstream in(err);
  std::string kept;
  for (std::string l; std::getline(in, l);)
    if (!is_progress_line(l)) kept += l + "\n";
  return kept;
}

}  // namespace haptex::test
