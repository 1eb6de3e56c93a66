#include "rig/scenario_runner.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <stdexcept>

#include "contact/equivalent_conicity.hpp"
#include "proto/role_table.hpp"
#include "rig/reference_model.hpp"

namespace tread::host {

void AnswerCheck::add(const AnswerCheck& other) {
  answers_checked += other.answers_checked;
  stale_answers += other.stale_answers;
  flagged_answers += other.flagged_answers;
  unchecked_cycles += other.unchecked_cycles;
  other_answers += other.other_answers;
  max_force_error_n = std::max(max_force_error_n, other.max_force_error_n);
  max_moment_error_nm = std::max(max_moment_error_nm, other.max_moment_error_nm);
  max_delta_r_error_mm = std::max(max_delta_r_error_mm, other.max_delta_r_error_mm);
  max_force_n = std::max(max_force_n, other.max_force_n);
}

ScenarioRunner::ScenarioRunner(RigScenario& scenario, proto::RigLink& link, proto::Layout layout,
                               std::uint8_t wheels, std::uint8_t wheelsets,
                               const RigReference& reference, std::uint8_t wheelset_forces)
    : scenario_(scenario),
      wheels_(wheels),
      wheelsets_(wheelsets),
      reference_(reference),
      link_(link),
      layout_(layout),
      columns_(scenario.trace_columns()) {
  // The node's output messages of one cycle: its status and every message carrying a configured
  // channel (as the node chooses them).
  const auto all = proto::messages(layout);
  for (std::size_t m = 0; m < all.size(); ++m) {
    if (all[m].direction != proto::Direction::node_to_rig) {
      continue;
    }
    bool sent = all[m].id == proto::kNodeStatusId;
    for (const proto::SignalSpec& sig : all[m].signals) {
      const proto::RoleScope scope = proto::role_scope(sig.role);
      const int channel = all[m].instance_of(sig);
      const bool wheel = scope == proto::RoleScope::wheel;
      const bool wheelset = scope == proto::RoleScope::wheelset;
      const bool rail_wheel = scope == proto::RoleScope::rail_wheel;
      sent = sent || (wheel && channel >= 0 && channel < wheels) ||
             (wheelset && channel >= 0 && channel < wheelsets) ||
             (rail_wheel && channel >= 0 && channel / 2 < wheelset_forces);
    }
    if (sent) {
      expected_mask_ |= std::uint64_t{1} << m;
    }
  }
  const auto rows = static_cast<std::size_t>(scenario.duration_s() * 1000.0) + 2;
  trace_.reserve(rows * (columns_.size() + 1));
  row_.reserve(columns_.size());
}

std::span<const proto::CanFrame> ScenarioRunner::begin_cycle(double t_s, std::uint32_t rig_cycle) {
  proto::RigData d{};
  scenario_.inputs(t_s, d);
  d.rig_cycle = rig_cycle;
  frame_count_ = link_.encode_cycle(d, frames_);
  rig_cycle_ = rig_cycle;
  cycle_open_ = true;
  received_mask_ = 0;
  // Until a NodeStatus starts this cycle's answer, frames are the rest of another computation's.
  other_answer_ = true;
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
  if (frame.id == proto::kNodeStatusId) {
    // The node sends its status first: a status starts an answer, so frames of two computations
    // are never merged. In sync mode it names the rig cycle it answers. Between cycles (after
    // end_cycle, before begin_cycle) nothing is an answer.
    if (link_.receive(frame, other_) != Status::ok) {
      return false;
    }
    received_mask_ = 0;
    other_answer_ = !cycle_open_ || !proto::answers_rig_cycle(other_.status, rig_cycle_);
    if (other_answer_) {
      ++check_.other_answers;
      return false;
    }
    answers_.status = other_.status;
  } else if (link_.receive(frame, other_answer_ ? other_ : answers_) != Status::ok ||
             other_answer_) {
    return false;
  }
  const proto::MessageSpec* m = proto::find_message(layout_, frame.id);
  received_mask_ |= std::uint64_t{1} << proto::message_index(layout_, *m);
  return (received_mask_ & expected_mask_) == expected_mask_;
}

void ScenarioRunner::end_cycle(double dt_s, bool answered) {
  cycle_open_ = false;
  other_answer_ = true;
  check_.unchecked_cycles += answered ? 0U : 1U;
  for (std::size_t i = 0; i < wheels_ && answered && reference_.tyre != nullptr; ++i) {
    const proto::WheelOutput& w = answers_.wheels[i];
    if (w.status != 0U) {
      const bool stale = (w.status & proto::kStatusStale) != 0U;
      check_.stale_answers += stale ? 1U : 0U;
      check_.flagged_answers += stale ? 0U : 1U;
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
  for (std::size_t j = 0; j < wheelsets_ && answered && reference_.contact != nullptr; ++j) {
    const proto::WheelsetOutput& w = answers_.wheelsets[j];
    if (w.status != 0U) {
      const bool stale = (w.status & proto::kStatusStale) != 0U;
      check_.stale_answers += stale ? 1U : 0U;
      check_.flagged_answers += stale ? 0U : 1U;
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

ScenarioOutcome finish_scenario(ScenarioRunner& runner, const std::filesystem::path& out_dir,
                                bool plot) {
  RigScenario& scenario = runner.scenario();
  ScenarioOutcome o;
  o.name = scenario.name();
  o.description = scenario.description();
  o.cycles = runner.cycles();
  o.check = runner.check();
  o.metrics = scenario.metrics();
  std::filesystem::create_directories(out_dir);
  o.trace_csv = out_dir / (o.name + ".csv");
  runner.write_trace(o.trace_csv);
  if (plot) {
    o.plots = scenario.plot(o.trace_csv, out_dir);
  }
  return o;
}

void print_scenario_outcome(std::ostream& out, const ScenarioOutcome& o) {
  out << "\n== " << o.name << " — " << o.description << "\n";
  out << "   " << o.cycles << " cycles; " << o.check.answers_checked
      << " answers checked against the reference";
  if (o.check.stale_answers > 0) out << " (" << o.check.stale_answers << " stale)";
  if (o.check.flagged_answers > 0) {
    out << "; " << o.check.flagged_answers
        << " answers flagged clamped, saturated or disabled (not checked)";
  }
  if (o.check.unchecked_cycles > 0) {
    out << "; " << o.check.unchecked_cycles << " cycles without an answer in time (not checked)";
  }
  if (o.check.other_answers > 0) {
    out << "; " << o.check.other_answers << " answers of the node to no cycle the rig waited for";
  }
  out << "\n";
  for (const ScenarioMetric& m : o.metrics) {
    out << "   " << std::left << std::setw(36) << m.name << std::right << std::setw(11)
        << std::setprecision(5) << m.value << ' ' << std::left << std::setw(6) << m.unit
        << std::right << m.note << "\n";
  }
  out << "   trace " << o.trace_csv.string();
  for (const auto& p : o.plots) out << "   plot " << p.string();
  out << "\n";
}

}  // namespace tread::host
