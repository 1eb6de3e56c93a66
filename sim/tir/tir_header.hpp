#pragma once
// Turns a parsed .tir into a self-contained constexpr C++ header, so an ECU build can flash a tyre
// without a file system. The generated header needs only <cstddef> and <string_view> (usable in a
// freestanding, no-heap build) and contains:
//
//   namespace tread::tir {      // defined once (guarded by TREAD_TIR_TABLE_TYPES)
//   struct TirEntry { std::string_view section, key; bool is_number; double number;
//                     std::string_view text; };     // text: quoted content or token as written
//   struct TirTableRow { std::string_view section; std::string_view row; };
//   constexpr const TirEntry* find_entry(entries, section, key);   // ASCII case-insensitive
//   constexpr double number_or(entries, section, key, fallback);
//   }
//   namespace <ns> {
//   inline constexpr tread::tir::TirEntry <name>[] = {{"MODEL", "FITTYP", true, 61.0, "61"}, ...};
//   inline constexpr tread::tir::TirTableRow <name>Tables[] = {{"SHAPE", " 1.0 0.0"}, ...};
//   inline constexpr std::string_view <name>Source = "<file name>";
//   }
//
// Numbers are written in shortest round-trip form, so each `number` equals the double read_tir()
// gives for the same entry, bit for bit. Every entry of every key/value section is included in file
// order (unknown keys too); comments are dropped.

#include <string>

#include "tir/tir_file.hpp"

namespace tread::tir {

struct HeaderOptions {
  std::string name = "kTyre";        ///< C++ identifier of the entry array
  std::string name_space = "tyres";  ///< namespace of the arrays (may contain ::)
};

/// The header text. Throws TirError if `options` holds an invalid identifier.
std::string generate_header(const TirFile& file, const HeaderOptions& options);

}  // namespace tread::tir
