#pragma once
// Base64 (RFC 4648, with padding), for data: URIs in a self-contained page.
#include <string>
#include <string_view>

namespace haptex::text {

std::string base64(std::string_view bytes);

}  // namespace haptex::text
