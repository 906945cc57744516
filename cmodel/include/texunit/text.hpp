// Error-message text. Bytes quoted from a user's file (JSON keys and strings, vector-file tokens)
// can be anything: a message shows control bytes escaped (\xHH), so that a NUL cannot cut it
// (std::exception::what() is a C string) and a control byte cannot garble the terminal.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace tu {

inline std::string printable(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\n' || c == '\t' || (c >= 0x20 && c != 0x7f)) {
      out += ch;
    } else {
      char b[8];
      std::snprintf(b, sizeof b, "\\x%02x", c);
      out += b;
    }
  }
  return out;
}

}  // namespace tu
