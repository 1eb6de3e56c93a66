#pragma once
// Checks for names the header generators write into C++ source (identifiers, namespace paths).

#include <string_view>

namespace tread::tir {

/// A C++ identifier: [A-Za-z_][A-Za-z0-9_]*.
inline bool is_identifier(std::string_view s) {
  if (s.empty()) return false;
  auto start = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  if (!start(s.front())) return false;
  for (const char c : s) {
    if (!start(c) && !(c >= '0' && c <= '9')) return false;
  }
  return true;
}

/// A namespace path: identifiers joined by "::".
inline bool is_namespace(std::string_view s) {
  while (true) {
    const auto pos = s.find("::");
    if (!is_identifier(s.substr(0, pos))) return false;
    if (pos == std::string_view::npos) return true;
    s.remove_prefix(pos + 2);
  }
}

}  // namespace tread::tir
