#include "apps/terminal_progress.hpp"

#include <unistd.h>

#include <cstdio>

#include "core/text/utf8.hpp"

namespace haptex::apps {

Progress terminal_progress(const GlobalOptions& global, const std::string& label) {
  if (global.quiet || !isatty(STDERR_FILENO)) return {};
  // Written with stdio, beside std::cerr's filter (apps/printable_stream.hpp): the item's name is escaped here.
  return [label](std::size_t done, std::size_t total, std::string_view what) {
    constexpr int width = 30;
    const int filled = total ? int(width * done / total) : width;
    std::fprintf(stderr, "\r%s [%.*s%*s] %zu/%zu %.40s\033[K", label.c_str(), filled,
                 "##############################", width - filled, "", done, total, text::printable(what).c_str());
    if (done == total) std::fputc('\n', stderr);
    std::fflush(stderr);
  };
}

}  // namespace haptex::apps
