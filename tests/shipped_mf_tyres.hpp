#pragma once
// Every Magic Formula tyre the project ships (data/tyres/*.tir), in file-name order, each file read
// once. The PAC89 and PAC94 files there are other models: left out by their detected model, so
// that a Magic Formula file that fails to load fails the test instead of being skipped.

#include <algorithm>
#include <filesystem>
#include <vector>

#include "golden_path.hpp"
#include "mf/mf_parameters.hpp"
#include "tir/tir_file.hpp"
#include "tir/tir_model.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::testing {

struct ShippedMfTyre {
  std::filesystem::path file;
  tyre::MfTirParameters loaded;
};

inline std::vector<ShippedMfTyre> shipped_mf_tyre_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(tyres_dir())) {
    if (entry.path().extension() == ".tir") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<ShippedMfTyre> tyres;
  for (const std::filesystem::path& file : files) {
    const tir::TirFile tir = tir::read_tyre_property_file(file);
    if (tir::detect_model(tir).is_magic_formula()) {
      tyres.push_back({file, tyre::mf_parameters_from_tir(tir)});
    }
  }
  return tyres;
}

inline std::vector<mf::MfParameters<double>> shipped_mf_tyres() {
  std::vector<mf::MfParameters<double>> params;
  for (const ShippedMfTyre& t : shipped_mf_tyre_files()) params.push_back(t.loaded.params);
  return params;
}

}  // namespace tread::testing
