#pragma once
// A page haptex wrote, opened in headless Chromium as a user's browser opens it: what its load check
// recorded (page/html_page.hpp: images loaded, image errors, every audio element's duration, audio
// errors), and a screenshot.
#include <nlohmann/json.hpp>
#include <string>

namespace haptex::test {

bool browser_installed();
// Opens `page` (a file path); returns the load check's JSON (null when it did not finish), saving a
// screenshot to `screenshot` when that is not empty.
nlohmann::json browser_load_check(const std::string& page, const std::string& screenshot = "");

}  // namespace haptex::test
