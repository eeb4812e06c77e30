#include "apps/terminal_progress.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>

#include "core/text/utf8.hpp"

namespace haptex::apps {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kLogEvery = std::chrono::seconds(10);

// Written with stdio, beside std::cerr's filter (apps/printable_stream.hpp): the item's name is escaped here.
Progress bar(const std::string& label) {
  return [label](std::size_t done, std::size_t total, std::string_view what) {
    constexpr int width = 30;
    const int filled = total ? int(width * done / total) : width;
    std::fprintf(stderr, "\r%s [%.*s%*s] %zu/%zu %.40s\033[K", label.c_str(), filled,
                 "##############################", width - filled, "", done, total, text::printable(what).c_str());
    if (done == total) std::fputc('\n', stderr);
    std::fflush(stderr);
  };
}

Progress log_lines(const std::string& label) {
  const auto start = Clock::now();
  auto last = std::make_shared<Clock::time_point>(start);
  return [label, last, start](std::size_t done, std::size_t total, std::string_view what) {
    const Clock::time_point now = Clock::now();
    if (done != total && now - *last < kLogEvery) return;
    *last = now;
    std::fprintf(stderr, "%s: %zu/%zu %.60s (%.0f s)\n", label.c_str(), done, total, text::printable(what).c_str(),
                 std::chrono::duration<double>(now - start).count());
    std::fflush(stderr);
  };
}

}  // namespace

Progress terminal_progress(const GlobalOptions& global, const std::string& label) {
  if (global.quiet) return {};
  return isatty(STDERR_FILENO) ? bar(label) : log_lines(label);
}

}  // namespace haptex::apps
