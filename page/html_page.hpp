#pragma once
// The pages haptex writes for a browser (evaluate's report.html, `haptex view`'s index.html): one
// self-contained HTML file each, everything embedded, nothing loaded from the network. Their common
// frame: the style, a script that sorts a table (class "sortable") by the column clicked, and the load
// check: the script records every image that fails and every audio element's duration, as JSON, in
// the element with id "load-check" (marked data-done="1" once all have answered), which the tests
// read from a headless browser.
#include <string>

namespace haptex::page {

// <!doctype html> .. </html> around `body` (HTML), titled `title` (text).
std::string html_page(const std::string& title, const std::string& body);

}  // namespace haptex::page
