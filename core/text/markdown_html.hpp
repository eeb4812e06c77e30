#pragma once
// The Markdown haptex writes (its reports), as HTML: headings (#, ##, ###), paragraphs, pipe tables,
// "- " lists, images on a line of their own, and inline `code`, **bold**, *emphasis*, [links](url)
// and backslash escapes. Everything else is text. All text is HTML-escaped before any markup is made,
// so a material's name never becomes markup. Not a general Markdown renderer: what it is given is
// report_markdown's output (docs/evaluate.md, "The report").
#include <functional>
#include <string>
#include <string_view>

namespace haptex::text {

// `image_source` turns an image's file name into what its <img src> holds (a data: URI, or the name);
// empty: the image is left out, its alt text kept in its place.
std::string markdown_html(std::string_view markdown, const std::function<std::string(const std::string& file)>& image_source);

// &, <, >, " and ' as entities.
std::string html_escaped(std::string_view text);

}  // namespace haptex::text
