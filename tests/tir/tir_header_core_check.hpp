#pragma once
/// FNOMIN of MagicFormula61_Parameters.tir, looked up at compile time in a core-flags TU.
double core_check_fnomin() noexcept;
