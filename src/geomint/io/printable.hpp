#pragma once
// A value or path as a message shows it: on one line (control characters escaped: \n, \r, \t, \xNN),
// and, over kShownChars characters, by its start and end with the count between (a refusal stays a
// line or two, whatever was given).
#include <string>
#include <string_view>

namespace geomint {

inline constexpr std::size_t kShownChars = 200;

inline std::string printable(std::string_view s) {
  static const char* const kHex = "0123456789abcdef";
  const auto escaped = [](std::string_view part) {
    std::string out;
    for (const char c : part) {
      const auto u = static_cast<unsigned char>(c);
      if (c == '\n') out += "\\n";
      else if (c == '\r') out += "\\r";
      else if (c == '\t') out += "\\t";
      else if (u < 0x20 || u == 0x7f) out += std::string("\\x") + kHex[u >> 4] + kHex[u & 15];
      else out += c;
    }
    return out;
  };
  if (s.size() <= kShownChars) return escaped(s);
  constexpr std::size_t head = 120, tail = 60;
  return escaped(s.substr(0, head)) + "...(" + std::to_string(s.size()) + " characters)..." + escaped(s.substr(s.size() - tail));
}

}  // namespace geomint
