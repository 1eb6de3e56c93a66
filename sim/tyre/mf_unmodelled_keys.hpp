#pragma once
// Keys of a Magic Formula .tir that tread reads past: a coefficient that would change a steady-state
// output but is not in tread's model (LMUV, Q_FZ3, Q_CAM, MC_CONTOUR_A/B, a key tread does not
// know at all) is named in a warning when its value is not the one that switches its term off
// (1 for a scaling factor, 0 for LMUV and every other coefficient), so that no output is silently
// different from what the file describes.
//
// Not warned about: the model's own parameters, Q_FZ1 (derived from VERTICAL_STIFFNESS, as MFeval
// does), and what only a transient or structural tyre model uses (inertia, damping, bottoming,
// belt dynamics, the gyroscopic terms QTZ1/MBELT/LGYR, [STRUCTURAL], [CONTACT_PATCH]).
#include <string>

#include "tir/tir_file.hpp"
#include "tir/tir_model.hpp"

namespace tread::tyre {

/// Appends one line to `warning` (newline-separated) naming the keys of another Magic Formula
/// generation than `model` whose values differ from what tread assumes without them (an MF 6.2
/// file given FITTYP 61: Q_FCY2, Q_CAM1-3, Q_FYS1-3 unread; an MF 6.1 file as MF 5.2: PKY4-7,
/// PPX1 …): nothing, if there are none.
void warn_other_model_keys(const tir::TirFile& file, const tir::DetectedModel& model,
                           std::string& warning);

/// Appends one `file:line: …` warning line per such key to `warning` (newline-separated).
void warn_unmodelled_keys(const tir::TirFile& file, const std::string& model_name,
                          std::string& warning);

}  // namespace tread::tyre
