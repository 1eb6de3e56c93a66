#include "rig/scenario_runner.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <stdexcept>

#include "contact/equivalent_conicity.hpp"
#include "rig/reference_model.hpp"

namespace tread::host {

ScenarioRunner::ScenarioRunner(RigScenario& scenario, proto::RigLink& link, proto::Layout layout,
                               std::uint8_t wheels, std::uint8_t wheelsets,
                               const RigReference& reference)
    : scenario_(scenario),
      wheels_(wheels),
      wheelsets_(wheelsets),
      reference_(reference),
      link_(link),
      layout_(layout),
      columns_(scenario.trace_columns()) {
  const auto rows = static_cast<std::size_t>(scenario.duration_s() * 1000.0) + 2;
  trace_.reserve(rows * (columns_.size() + 1));
  row_.reserve(columns_.size());
}

std::span<const proto::CanFrame> ScenarioRunner::begin_cycle(double t_s, std::uint32_t rig_cycle) {
  proto::RigData d{};
  scenario_.inputs(t_s, d);
  d.rig_cycle = rig_cycle;
  frame_count_ = link_.encode_cycle(d, frames_);
  // The inputs as the node decodes them (after quantisation): the reference is evaluated on these.
  for (std::size_t k = 0; k < frame_count_; ++k) {
    const proto::MessageSpec* m = proto::find_message(layout_, frames_[k].id);
    if (m != nullptr) {
      static_cast<void>(proto::decode(*m, frames_[k], seen_));
    }
  }
  return {frames_.data(), frame_count_};
}

bool ScenarioRunner::on_frame(const proto::CanFrame& frame) {
  if (frame.error || frame.extended) {
    return false;
  }
  return link_.receive(frame, answers_) == Status::ok && frame.id == proto::kNodeStatusId;
}

void ScenarioRunner::end_cycle(double dt_s) {
  for (std::size_t i = 0; i < wheels_ && reference_.tyre != nullptr; ++i) {
    const proto::WheelOutput& w = answers_.wheels[i];
    if (w.status != 0U) {
      check_.stale_answers += (w.status & proto::kStatusStale) != 0U ? 1U : 0U;
      continue;
    }
    const mf::MfOutput<double> ref =
        reference_output(*reference_.tyre, seen_.wheels[i], reference_.options);
    ++check_.answers_checked;
    check_.max_force_error_n =
        std::max({check_.max_force_error_n, std::abs(static_cast<double>(w.fx_n) - ref.fx_n),
                  std::abs(static_cast<double>(w.fy_n) - ref.fy_n)});
    check_.max_moment_error_nm =
        std::max(check_.max_moment_error_nm, std::abs(static_cast<double>(w.mz_nm) - ref.mz_nm));
    check_.max_force_n = std::max({check_.max_force_n, std::abs(ref.fx_n), std::abs(ref.fy_n)});
  }
  for (std::size_t j = 0; j < wheelsets_ && reference_.contact != nullptr; ++j) {
    const proto::WheelsetOutput& w = answers_.wheelsets[j];
    if (w.status != 0U) {
      check_.stale_answers += (w.status & proto::kStatusStale) != 0U ? 1U : 0U;
      continue;
    }
    ++check_.answers_checked;
    const double ref = contact::delta_r_at(*reference_.contact,
                                           static_cast<double>(seen_.wheelsets[j].lateral_mm));
    check_.max_delta_r_error_mm =
        std::max(check_.max_delta_r_error_mm, std::abs(static_cast<double>(w.delta_r_mm) - ref));
  }
  scenario_.advance(seen_, answers_, dt_s);
  t_s_ += dt_s;
  ++cycles_;
  row_.clear();
  scenario_.trace_values(row_);
  if (row_.size() != columns_.size()) {
    throw std::logic_error(scenario_.name() + ": trace row has " + std::to_string(row_.size()) +
                           " values for " + std::to_string(columns_.size()) + " columns");
  }
  trace_.push_back(t_s_);
  trace_.insert(trace_.end(), row_.begin(), row_.end());
}

void ScenarioRunner::write_trace(const std::filesystem::path& csv) const {
  std::ofstream out(csv);
  out << "t_s";
  for (const std::string& c : columns_) {
    out << ',' << c;
  }
  out << '\n' << std::setprecision(9);
  const std::size_t width = columns_.size() + 1;
  for (std::size_t r = 0; r + width <= trace_.size(); r += width) {
    for (std::size_t k = 0; k < width; ++k) {
      out << (k == 0 ? "" : ",") << trace_[r + k];
    }
    out << '\n';
  }
  if (!out) {
    throw std::runtime_error("cannot write " + csv.string());
  }
}

}  // namespace tread::host
