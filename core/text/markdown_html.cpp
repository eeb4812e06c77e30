#include "core/text/markdown_html.hpp"

#include <cctype>
#include <sstream>
#include <vector>

namespace haptex::text {
namespace {

std::size_t run_of(std::string_view line, std::size_t at, char c) {
  std::size_t n = 0;
  while (at + n < line.size() && line[at + n] == c) ++n;
  return n;
}

// A code span opened by `fence` backticks at `at` (CommonMark): it ends at the next run of exactly as
// many, so a name holding a backtick is written in a longer fence; one space each side is padding.
// Returns the span's end, or npos when it is not closed.
std::size_t code_span(std::string_view line, std::size_t at, std::size_t fence, std::string& out) {
  for (std::size_t i = at + fence; i < line.size();) {
    const std::size_t n = run_of(line, i, '`');
    if (n == fence) {
      std::string_view content = line.substr(at + fence, i - at - fence);
      if (content.size() >= 2 && content.front() == ' ' && content.back() == ' ') content = content.substr(1, content.size() - 2);
      out += "<code>" + std::string(content) + "</code>";
      return i + n;
    }
    i += n == 0 ? 1 : n;
  }
  return std::string_view::npos;
}

// Inline markup of one line of escaped text: `code` (in any fence), **bold**, *emphasis*,
// [text](url), and a backslash before any ASCII punctuation (CommonMark) for the character itself.
std::string inline_html(std::string_view line) {
  std::string out;
  bool bold = false, emphasis = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '\\' && i + 1 < line.size() && std::ispunct(static_cast<unsigned char>(line[i + 1]))) {
      out += line[++i];
    } else if (c == '`') {
      const std::size_t fence = run_of(line, i, '`'), end = code_span(line, i, fence, out);
      if (end == std::string_view::npos) {
        out += std::string(fence, '`');
        i += fence - 1;
      } else {
        i = end - 1;
      }
    } else if (c == '*' && i + 1 < line.size() && line[i + 1] == '*') {
      out += bold ? "</strong>" : "<strong>";
      bold = !bold;
      ++i;
    } else if (c == '*') {
      out += emphasis ? "</em>" : "<em>";
      emphasis = !emphasis;
    } else if (c == '[') {
      const std::size_t close = line.find("](", i), end = close == std::string_view::npos ? close : line.find(')', close);
      if (end == std::string_view::npos) {
        out += c;
        continue;
      }
      // Only a file beside the page: a target with a scheme (javascript:, http:) stays text.
      const std::string_view target = line.substr(close + 2, end - close - 2);
      if (target.find(':') != std::string_view::npos) {
        out += c;
        continue;
      }
      out += "<a href=\"" + std::string(target) + "\">" + inline_html(line.substr(i + 1, close - i - 1)) + "</a>";
      i = end;
    } else {
      out += c;
    }
  }
  if (bold) out += "</strong>";
  if (emphasis) out += "</em>";
  return out;
}

std::vector<std::string> cells(std::string_view row) {
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t i = 1; i < row.size(); ++i) {  // row starts with '|'
    if (row[i] == '\\' && i + 1 < row.size() && row[i + 1] == '|') {  // GFM: a cell's escaped pipe is a pipe, in code too
      cell += '|';
      ++i;
    } else if (row[i] == '|') {
      out.push_back(cell);
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  for (std::string& c : out) {
    while (!c.empty() && c.front() == ' ') c.erase(c.begin());
    while (!c.empty() && c.back() == ' ') c.pop_back();
  }
  return out;
}

class Renderer {
 public:
  explicit Renderer(const std::function<std::string(const std::string&)>& image_source) : image_source_(image_source) {}

  void line(const std::string& raw) {
    if (raw.rfind("![", 0) == 0 && raw.find("](") != std::string::npos && raw.back() == ')') {
      end_table();
      end_list();
      return image(raw);
    }
    const std::string text = html_escaped(raw);
    if (text.rfind('|', 0) == 0) return table_row(text);
    end_table();
    if (text.empty()) return end_blocks();
    if (text.rfind("- ", 0) == 0) {
      end_paragraph();
      if (!list_) out_ << "<ul>\n";
      list_ = true;
      out_ << "<li>" << inline_html(std::string_view(text).substr(2)) << "</li>\n";
      return;
    }
    end_list();
    if (const std::size_t level = text.find_first_not_of('#'); level >= 1 && level <= 6 && text[0] == '#' && text[level] == ' ') {
      end_paragraph();
      const std::string title = text.substr(level + 1), tag = "h" + std::to_string(level);
      out_ << "<" << tag << " id=\"" << anchor(raw.substr(level + 1)) << "\">" << inline_html(title) << "</" << tag << ">\n";
      return;
    }
    out_ << (paragraph_ ? "\n" : "<p>") << inline_html(text);
    paragraph_ = true;
  }

  std::string finish() {
    end_table();
    end_blocks();
    return out_.str();
  }

 private:
  void image(const std::string& raw) {
    end_paragraph();
    const std::size_t close = raw.find("](");
    const std::string alt = html_escaped(raw.substr(2, close - 2)), file = raw.substr(close + 2, raw.size() - close - 3);
    const std::string source = image_source_(file);
    if (source.empty())
      out_ << "<p><em>" << alt << "</em></p>\n";
    else
      out_ << "<figure><img src=\"" << source << "\" alt=\"" << alt << "\"><figcaption>" << alt << "</figcaption></figure>\n";
  }
  void table_row(const std::string& text) {
    end_paragraph();
    end_list();
    const std::vector<std::string> row = cells(text);
    if (!row.empty() && row[0].find_first_not_of("-:") == std::string::npos) return;  // the |---| rule
    if (!table_) {
      out_ << "<table class=\"sortable\">\n<thead><tr>";
      for (const std::string& c : row) out_ << "<th>" << inline_html(c) << "</th>";
      out_ << "</tr></thead>\n<tbody>\n";
      table_ = true;
      return;
    }
    out_ << "<tr>";
    for (const std::string& c : row) out_ << "<td>" << inline_html(c) << "</td>";
    out_ << "</tr>\n";
  }
  // Letters and digits of the raw title, lower case, other runs as one '-' (only ASCII: safe in an id).
  static std::string anchor(const std::string& raw_title) {
    std::string a;
    for (const char c : raw_title)
      if (std::isalnum(static_cast<unsigned char>(c))) a += char(std::tolower(static_cast<unsigned char>(c)));
      else if (!a.empty() && a.back() != '-') a += '-';
    while (!a.empty() && a.back() == '-') a.pop_back();
    return a;
  }
  void end_table() {
    if (table_) out_ << "</tbody>\n</table>\n";
    table_ = false;
  }
  void end_paragraph() {
    if (paragraph_) out_ << "</p>\n";
    paragraph_ = false;
  }
  void end_list() {
    if (list_) out_ << "</ul>\n";
    list_ = false;
  }
  void end_blocks() {
    end_paragraph();
    end_list();
  }

  const std::function<std::string(const std::string&)>& image_source_;
  std::ostringstream out_;
  bool table_ = false, paragraph_ = false, list_ = false;
};

}  // namespace

std::string html_escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string markdown_html(std::string_view markdown, const std::function<std::string(const std::string& file)>& image_source) {
  Renderer r(image_source);
  std::size_t start = 0;
  while (start <= markdown.size()) {
    const std::size_t end = markdown.find('\n', start);
    r.line(std::string(markdown.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start)));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return r.finish();
}

}  // namespace haptex::text
