#pragma once
// Every Magic Formula tyre the project ships (data/tyres/*.tir), in file-name order. The PAC89 and
// PAC94 files there are other models: left out by their detected model, so that a Magic Formula
// file that fails to load fails the test instead of being skipped.

#include <algorithm>
#include <filesystem>
#include <vector>

#include "golden_path.hpp"
#include "mf/mf_parameters.hpp"
#include "tir/tir_file.hpp"
#include "tir/tir_model.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::testing {

inline std::vector<std::filesystem::path> shipped_mf_tyre_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(tyres_dir())) {
    if (entry.path().extension() == ".tir" &&
        tir::detect_model(tir::read_tir(entry.path())).is_magic_formula()) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

inline std::vector<mf::MfParameters<double>> shipped_mf_tyres() {
  std::vector<mf::MfParameters<double>> tyres;
  for (const std::filesystem::path& file : shipped_mf_tyre_files()) {
    tyres.push_back(tyre::load_mf_parameters(file).params);
  }
  return tyres;
}

}  // namespace tread::testing
