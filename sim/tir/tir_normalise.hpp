#pragma once
// A normalised rewrite of a .tir file: the same sections, keys, values and table rows, in file
// order, without the original's comments, blank lines or alignment. This is how tread ships the
// property files it did not write (data/tyres/): the numbers carry over exactly (each value keeps
// the text it was written with), third-party prose does not.
//
// Output layout:
//   $ <one line that says where the file came from, given by the caller>
//   [SECTION]
//   KEY                      = value
//   ...
// Quoted values keep their quote character; table sections keep their rows (column headers such
// as `{pen fz}` included), trimmed and without trailing comments.

#include <string>

#include "tir/tir_file.hpp"

namespace tread::tir {

/// The normalised text of `file`; `note` (one line, may be empty) becomes the first line as a
/// `$` comment. Line ends are LF.
std::string write_normalised_tir(const TirFile& file, const std::string& note);

}  // namespace tread::tir
