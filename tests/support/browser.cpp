#include "tests/support/browser.hpp"

#include <vector>

#include "core/process/run_program.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {

bool browser_installed() { return process::program_on_path("chromium"); }

nlohmann::json browser_load_check(const std::string& page, const std::string& screenshot) {
  const TempDir profile;
  const std::string url = "file://" + page;
  const std::vector<std::string> headless = {"timeout", "120", "chromium", "--headless", "--no-sandbox", "--disable-gpu",
                                             "--user-data-dir=" + profile.path().string(), "--virtual-time-budget=20000"};
  std::vector<std::string> dump = headless;
  dump.insert(dump.end(), {"--dump-dom", url});
  const CommandResult r = run_program(dump);
  const std::string mark = "<pre id=\"load-check\" data-done=\"1\">";
  const std::size_t at = r.out.find(mark);
  if (r.exit_code != 0 || at == std::string::npos) return nullptr;
  const std::size_t from = at + mark.size();
  if (!screenshot.empty()) {
    std::vector<std::string> shot = headless;
    shot.insert(shot.end(), {"--window-size=1200,2400", "--screenshot=" + screenshot, url});
    run_program(shot);
  }
  return nlohmann::json::parse(r.out.substr(from, r.out.find("</pre>", from) - from));
}

}  // namespace haptex::test
