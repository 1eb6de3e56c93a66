#include "tir/tir_model.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>

#include "io/text_line.hpp"

namespace tread::tir {

namespace {

std::string upper(std::string_view s) {
  std::string out;
  for (const char c : s) out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  while (!out.empty() && out.back() == ' ') out.pop_back();
  while (!out.empty() && out.front() == ' ') out.erase(out.begin());
  return out;
}

enum class Format { kMagicFormula, kPac89, kPac94, kOther };

struct FormatRow {
  std::string_view name;  // PROPERTY_FILE_FORMAT, upper case
  Format format;
  std::string_view what;  // for kOther: the model it is
};

constexpr std::array kFormats = std::to_array<FormatRow>({
    {"USER", Format::kMagicFormula, ""},
    {"PAC2002", Format::kMagicFormula, ""},
    {"PAC-2002", Format::kMagicFormula, ""},
    {"PAC_2002", Format::kMagicFormula, ""},
    {"MF-TYRE", Format::kMagicFormula, ""},
    {"MF_TYRE", Format::kMagicFormula, ""},
    {"MFTYRE", Format::kMagicFormula, ""},
    {"MF_05", Format::kMagicFormula, ""},
    {"MF-05", Format::kMagicFormula, ""},
    {"MF5", Format::kMagicFormula, ""},
    {"MF52", Format::kMagicFormula, ""},
    {"MF61", Format::kMagicFormula, ""},
    {"MF62", Format::kMagicFormula, ""},
    {"PAC-TIME", Format::kMagicFormula, ""},
    {"PAC_TIME", Format::kMagicFormula, ""},
    {"PAC-MC", Format::kMagicFormula, ""},
    {"PAC_MC", Format::kMagicFormula, ""},
    {"TNO", Format::kMagicFormula, ""},
    {"MF-SWIFT", Format::kMagicFormula, ""},
    {"SWIFT", Format::kMagicFormula, ""},
    {"PAC89", Format::kPac89, ""},
    {"PAC94", Format::kPac94, ""},
    {"FIALA", Format::kOther, "a Fiala tyre model"},
    {"UA", Format::kOther, "a UA (University of Arizona) tyre model"},
    {"UATIRE", Format::kOther, "a UA (University of Arizona) tyre model"},
    {"UA_TIRE", Format::kOther, "a UA (University of Arizona) tyre model"},
    {"HARTY", Format::kOther, "a Harty tyre model"},
    {"FTIRE", Format::kOther, "an FTire model"},
    {"CDTIRE", Format::kOther, "a CDTire model"},
    {"5PT", Format::kOther, "a 5-point tyre model"},
    {"5.2.1", Format::kOther, "a UA tyre model (format 5.2.1)"},
});

struct FunctionRow {
  std::string_view contains;  // in FUNCTION_NAME, upper case
  std::string_view what;
};
constexpr std::array kFunctions = std::to_array<FunctionRow>({
    {"HTIRE", "a Harty tyre model"},
    {"FIAL", "a Fiala tyre model"},
    {"UATIRE", "a UA tyre model"},
    {"FTIRE", "an FTire model"},
    {"CDTIRE", "a CDTire model"},
});

struct FittypRow {
  int fittyp;
  TirModel model;
  std::string_view name;
  ModelSet keys;
};
constexpr std::array kFittyps = std::to_array<FittypRow>({
    {5, TirModel::kMf50, "MF-Tyre 5.0", model::kPac2002},
    {6, TirModel::kMf52, "MF 5.2", model::kMf52},
    {21, TirModel::kMf52, "MF 5.2", model::kMf52},
    {52, TirModel::kMf52, "MF 5.2", model::kMf52},
    {61, TirModel::kMf61, "MF 6.1", model::kMf61},
    {62, TirModel::kMf62, "MF 6.2", model::kMf62},
});

constexpr std::string_view kMf50Note =
    "evaluated with the MF 5.2 / PAC2002 equations, which share its coefficients; MFSAFE1-3 are "
    "ignored";

std::string mf50_note(const TirFile& file, const std::string& what) {
  std::string note = what + ": " + std::string(kMf50Note);
  const auto fe = file.text_any("FE_METHOD");
  if (fe && upper(*fe) == "YES") {
    note +=
        "; FE_METHOD = 'YES' asks for MF-Tyre 5.0's friction-ellipse combined slip, which tread "
        "does not implement: combined-slip outputs use the MF 5.2 weighting functions (pure-slip "
        "outputs are unaffected)";
  }
  return note;
}

/// The Magic Formula generation a PROPERTY_FILE_FORMAT names ("5", "6.1", "6.2"), or empty.
std::string_view version_named_by(const std::string& format) {
  for (const std::string_view f :
       {"PAC2002", "PAC-2002", "PAC_2002", "MF52", "MF_05", "MF-05", "MF5"}) {
    if (format == f) return "MF 5.x / PAC2002";
  }
  if (format == "MF61") return "MF 6.1";
  if (format == "MF62") return "MF 6.2";
  return {};
}

std::string_view version_group(TirModel model) {
  switch (model) {
    case TirModel::kMf61:
      return "MF 6.1";
    case TirModel::kMf62:
      return "MF 6.2";
    default:
      return "MF 5.x / PAC2002";
  }
}

[[noreturn]] void not_mf(const TirFile& file, const Entry* at, const std::string& reason) {
  throw TirError(file.origin(), at != nullptr ? at->line : 0,
                 "not a Magic Formula file: " + reason);
}

bool has_nonzero(const TirFile& file, std::initializer_list<std::string_view> keys) {
  for (const auto k : keys) {
    const Entry* e = file.find_any(k);
    if (e == nullptr || e->is_quoted()) continue;
    const std::optional<double> v = parse_number(e->value);
    if (!v || std::fabs(*v) > 0.0) return true;  // not a number: said where it is read
  }
  return false;
}

bool has_any(const TirFile& file, std::initializer_list<std::string_view> keys) {
  for (const auto k : keys) {
    if (file.find_any(k) != nullptr) return true;
  }
  return false;
}

DetectedModel pac(bool pac94) {
  DetectedModel d;
  d.model = pac94 ? TirModel::kPac94 : TirModel::kPac89;
  d.name = pac94 ? "PAC94" : "PAC89";
  d.keys = pac94 ? model::kPac94 : model::kPac89;
  return d;
}

}  // namespace

DetectedModel detect_model(const TirFile& file) {
  const Entry* format_entry = file.find_any("PROPERTY_FILE_FORMAT");
  const std::string format = format_entry != nullptr ? upper(format_entry->value) : "";
  const Entry* function_entry = file.find_any("FUNCTION_NAME");
  if (function_entry != nullptr) {
    const std::string fn = upper(function_entry->value);
    for (const auto& f : kFunctions) {
      if (fn.find(f.contains) != std::string::npos) {
        not_mf(file, function_entry,
               "FUNCTION_NAME '" + host::text::excerpt(function_entry->value) + "' is " +
                   std::string(f.what));
      }
    }
  }
  Format kind = Format::kMagicFormula;
  bool known_format = format.empty();
  for (const auto& f : kFormats) {
    if (f.name != format) continue;
    known_format = true;
    kind = f.format;
    if (kind == Format::kOther) {
      not_mf(file, format_entry,
             "PROPERTY_FILE_FORMAT '" + host::text::excerpt(format_entry->value) + "' is " +
                 std::string(f.what));
    }
  }
  // PAC94's own coefficients decide a file that does not say which it is: where they are all 0
  // (a PAC89 file listing them, as Adams writes it), the terms A8…A13, B8…B10 and C11…C17 mean
  // what PAC89 makes them, which PAC94 reads otherwise.
  const std::initializer_list<std::string_view> pac94_only = {"A14", "A15", "A16", "A17", "B11",
                                                              "B12", "B13", "C18", "C19", "C20"};
  const bool pac94_keys = has_nonzero(file, pac94_only);
  if (kind == Format::kPac89) return pac(false);
  if (kind == Format::kPac94) return pac(true);

  const Entry* fittyp_entry = file.find_any("FITTYP");
  const bool mf_keys =
      has_any(file, {"PCX1", "PDX1", "PKX1", "PCY1", "PDY1", "PKY1", "QBZ1", "QCZ1", "QDZ1"});
  if (fittyp_entry == nullptr) {
    if (!mf_keys && has_any(file, {"A0", "B0", "C0"})) {
      DetectedModel d = pac(pac94_keys);
      d.note = pac94_keys ? "no PROPERTY_FILE_FORMAT: read as PAC94 (a PAC94 coefficient is not 0)"
               : has_any(file, pac94_only)
                   ? "no PROPERTY_FILE_FORMAT: read as PAC89 (PAC94's A14…A17, B11…B13, "
                     "C18…C20 are all 0; PAC94 would read A8…A13 otherwise)"
                   : "no PROPERTY_FILE_FORMAT: read as PAC89 (no PAC94 coefficients)";
      return d;
    }
    if (!mf_keys) {
      not_mf(file, format_entry,
             "no FITTYP and none of the Magic Formula coefficients (PCX1, PDY1, PKY1, QBZ1, …)");
    }
    DetectedModel d;
    if (format == "MF_05" || format == "MF-05" || format == "MF5") {
      d.model = TirModel::kMf50;
      d.name = "MF-Tyre 5.0";
      d.keys = model::kPac2002;
      d.note = mf50_note(file, "PROPERTY_FILE_FORMAT '" + host::text::excerpt(format_entry->value) +
                                   "' without FITTYP (MF-Tyre 5.0)");
      return d;
    }
    if (format == "MF61" || format == "MF62") {
      // The file names its generation: evaluated as that (it was evaluated as PAC2002, its MF 6.x
      // pressure, camber and vertical terms unread, with only "no FITTYP" said).
      const bool mf62 = format == "MF62";
      d.model = mf62 ? TirModel::kMf62 : TirModel::kMf61;
      d.name = mf62 ? "MF 6.2" : "MF 6.1";
      d.keys = mf62 ? model::kMf62 : model::kMf61;
      d.note = "no FITTYP: evaluated as " + d.name + ", which PROPERTY_FILE_FORMAT '" +
               host::text::excerpt(format_entry->value) + "' names";
      return d;
    }
    d.model = TirModel::kPac2002;
    d.name = "PAC2002";
    d.keys = model::kPac2002;
    d.note = known_format ? "no FITTYP"
                          : "unknown PROPERTY_FILE_FORMAT '" +
                                host::text::excerpt(format_entry->value) + "' and no FITTYP";
    d.note += ": evaluated as Adams PAC2002 (MF 5.2 equations with LGAX/LGAY/LGAZ)";
    return d;
  }
  const std::optional<double> f = file.number_any("FITTYP");
  long code = std::lround(*f);
  if (std::fabs(*f - static_cast<double>(code)) > 1e-9) code = -1;
  for (const auto& row : kFittyps) {
    if (row.fittyp != code) continue;
    if (!mf_keys) {
      not_mf(file, fittyp_entry,
             "FITTYP " + std::to_string(code) +
                 " but none of the Magic Formula coefficients (PCX1, PDY1, PKY1, QBZ1, …)");
    }
    DetectedModel d;
    d.model = row.model;
    d.name = std::string(row.name);
    d.keys = row.keys;
    if (row.model == TirModel::kMf50) d.note = mf50_note(file, "FITTYP 5 (MF-Tyre 5.0)");
    const std::string_view named = version_named_by(format);
    if (!named.empty() && named != version_group(row.model)) {
      d.note += std::string(d.note.empty() ? "" : "; ") + "PROPERTY_FILE_FORMAT '" +
                host::text::excerpt(format_entry->value) + "' names " + std::string(named) +
                " but FITTYP " + std::to_string(code) + " is " + d.name + ": evaluated as " +
                d.name + " (FITTYP decides)";
    }
    if (!known_format) {
      d.note += std::string(d.note.empty() ? "" : "; ") + "unknown PROPERTY_FILE_FORMAT '" +
                host::text::excerpt(format_entry->value) + "': read as " + d.name + " from FITTYP";
    }
    return d;
  }
  throw TirError(file.origin(), fittyp_entry->line,
                 "FITTYP " + tir::format_number(*f) +
                     " is not a known Magic Formula version (expected 5, 6, 21, 52, 61 or 62)");
}

TirFile read_tyre_property_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TirError(path.string(), 0, "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  try {
    return parse_tir(text, path.string());
  } catch (const TirError& e) {
    // Is there any tyre-property-file section header at the start of a line?
    std::istringstream lines(text);
    std::string line;
    bool has_header = false;
    while (std::getline(lines, line)) {
      const std::string u = upper(line);
      for (const char* h : {"[MDI_HEADER]", "[MODEL]", "[UNITS]"}) {
        if (u.rfind(h, 0) == 0) has_header = true;
      }
    }
    if (has_header) throw;
    throw TirError(e.file(), e.line(),
                   "not a Magic Formula file: not a tyre property file (no [MDI_HEADER], "
                   "[UNITS] or [MODEL] section; the text does not parse: " +
                       std::string(e.what()).substr(e.file().size() + 1) + ")");
  }
}

}  // namespace tread::tir
