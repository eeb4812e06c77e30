#include "play/action_stream.hpp"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <vector>

#include "core/error.hpp"
#include "core/text/parse_number.hpp"

namespace haptex::play {
namespace {

constexpr std::size_t kLongestLine = 4096;  // a line of three numbers is far shorter; more is no action stream

// Commas separate fields exactly ("1,,50" holds an empty one); a line without commas is split at runs
// of spaces and tabs. Surrounding spaces, tabs and a CR are not part of a field.
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> out;
  const bool commas = line.find(',') != std::string::npos;
  std::string field;
  const auto finish = [&] {
    const std::string_view trimmed = text::trim(field);
    if (commas || !trimmed.empty()) out.emplace_back(trimmed);
    field.clear();
  };
  for (const char c : line) {
    if (commas ? c == ',' : (c == ' ' || c == '\t')) finish();
    else field += c;
  }
  finish();
  if (out.size() == 1 && out[0].empty()) out.clear();
  return out;
}

// A header names columns: letters, digits and '_' ("t,force,speed", "force speed"), none a number.
bool is_header(const std::vector<std::string>& fields) {
  return !fields.empty() && std::all_of(fields.begin(), fields.end(), [](const std::string& f) {
    return !f.empty() && !text::parse_number(f) &&
           std::all_of(f.begin(), f.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
  });
}

}  // namespace

std::optional<ActionLine> parse_action_line(const std::string& line, const std::string& source, std::size_t number, bool first) {
  const std::string where = "line " + std::to_string(number);
  const std::vector<std::string> fields = fields_of(line);
  if (first && is_header(fields)) return std::nullopt;
  if (fields.size() != 2 && fields.size() != 3)
    throw input_error(source, where, "holds " + std::to_string(fields.size()) + (fields.size() == 1 ? " field" : " fields"),
                      "Give one action per line: force speed, or t,force,speed (N, mm/s)");
  std::vector<double> values;
  for (const std::string& field : fields) {
    const std::optional<double> v = text::parse_stored_number(field);
    if (!v) throw input_error(source, where, text::describe_bad_number(field), "Give numbers: force in N, speed in mm/s");
    values.push_back(*v);
  }
  ActionLine out;
  out.force = float(values[values.size() - 2]);
  out.speed = float(values.back());
  if (out.force < 0 || out.speed < 0) throw input_error(source, where, "negative force or speed", "Give magnitudes: force in N, speed in mm/s");
  return out;
}

ActionStream::ActionStream(int fd, std::string source) : fd_(fd), source_(std::move(source)), reader_([this] { read_lines(); }) {}

ActionStream::~ActionStream() {
  closing_ = true;
  reader_.join();
}

void ActionStream::read_lines() {
  std::string pending;
  std::size_t number = 0;
  char chunk[4096];
  const auto finish = [&](std::exception_ptr error) {
    std::lock_guard lock(mutex_);
    error_ = error;
    ended_ = true;
    arrived_.notify_all();
  };
  bool seen_content = false;  // a header may be the first line that is not blank
  const auto take = [&](const std::string& text, Clock::time_point now) {
    if (text.find_first_not_of(" \t\r") == std::string::npos) return;  // a blank line carries no action
    const std::optional<ActionLine> line = parse_action_line(text, source_, number, !seen_content);
    seen_content = true;
    if (!line) return;
    std::lock_guard lock(mutex_);
    lines_.push_back(*line);
    lines_.back().arrived = now;
    arrived_.notify_all();
  };
  try {
    while (!closing_) {
      pollfd p{fd_, POLLIN, 0};
      const int ready = ::poll(&p, 1, 50);  // wakes to see closing_
      if (ready < 0 && errno == EINTR) continue;
      if (ready < 0) throw failure(source_ + ": cannot read it: " + std::strerror(errno));
      if (ready == 0) continue;
      const ssize_t n = ::read(fd_, chunk, sizeof chunk);
      if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
      if (n < 0) throw failure(source_ + ": cannot read it: " + std::strerror(errno));
      const Clock::time_point now = Clock::now();
      if (n == 0) {
        ++number;
        take(pending, now);
        break;
      }
      pending.append(chunk, std::size_t(n));
      for (std::size_t end; (end = pending.find('\n')) != std::string::npos; pending.erase(0, end + 1)) {
        ++number;
        take(pending.substr(0, end), now);
      }
      if (pending.size() > kLongestLine)
        throw input_error(source_, "line " + std::to_string(number + 1), "is longer than " + std::to_string(kLongestLine) + " bytes",
                          "Give one action per line: force speed, or t,force,speed");
    }
    finish(nullptr);
  } catch (...) {
    finish(std::current_exception());
  }
}

bool ActionStream::wait_for_first(const std::atomic<bool>& stop) {
  std::unique_lock lock(mutex_);
  while (lines_.empty() && !ended_ && !stop) arrived_.wait_for(lock, std::chrono::milliseconds(50));
  return !lines_.empty();
}

std::exception_ptr ActionStream::error() {
  std::lock_guard lock(mutex_);
  return error_;
}

bool ActionStream::take(Clock::time_point until, std::deque<ActionLine>& out) {
  out.clear();
  std::lock_guard lock(mutex_);
  while (!lines_.empty() && lines_.front().arrived <= until) {
    out.push_back(lines_.front());
    lines_.pop_front();
  }
  return !(ended_ && lines_.empty() && out.empty());
}

}  // namespace haptex::play
