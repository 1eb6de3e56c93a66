// Uses an installed tread: one Magic Formula evaluation in float (MF 6.1 with the book's default
// coefficients) and one lookup in the first flashed wheel–rail contact table. The includes are the
// ones the tread tree itself writes.
#include <cmath>
#include <cstdint>

#include "core/status.hpp"
#include "hal_concepts.hpp"
#include "lut/tread_lut.hpp"
#include "mf/mf_evaluate.hpp"
#include "rail/contact_lookup.hpp"

#ifndef TREAD_CONSUMER_BARE_METAL
#include <cstdio>
#endif

namespace {

// The application's own clock, checked against tread's HAL concept.
struct TickClock {
  std::int64_t now_ns() const noexcept { return 0; }
  tread::Status sleep_until_ns(std::int64_t /*deadline_ns*/) noexcept { return tread::Status::ok; }
};
static_assert(tread::hal::Clock<TickClock>);

struct Results {
  tread::mf::MfOutput<float> tyre;
  tread::Result<tread::rail::ContactSample> contact;
  const char* pair;
};

Results run() {
  const tread::mf::MfParameters<float> params{};
  tread::mf::MfInput<float> input{};
  input.fz_n = 4000.0F;
  input.kappa = 0.05F;
  input.alpha_rad = 0.02F;
  input.vx_mps = 16.7F;
  Results r{};
  r.tyre = tread::mf::evaluate(params, input, tread::mf::MfOptions{});
  const auto pairs = tread::lut::contact_pairs();
  if (!pairs.empty()) {
    r.pair = pairs[0].name;
    r.contact = tread::rail::lookup(pairs[0].f32, 3.0F);
  }
  return r;
}

}  // namespace

#ifdef TREAD_CONSUMER_BARE_METAL

volatile float g_sink;  // keeps the results observable

int main() {
  const Results r = run();
  g_sink = r.tyre.fx_n + r.tyre.fy_n + r.tyre.mz_nm + r.contact.value.delta_r_mm;
  return 0;
}

#else

int main() {
  const Results r = run();
  const auto& t = r.tyre;
  const auto& c = r.contact.value;
  std::printf("MF 6.1 float, Fz 4000 N, kappa 0.05, alpha 0.02 rad, 16.7 m/s: status %s\n",
              tread::to_string(t.status));
  std::printf("  Fx %.1f N  Fy %.1f N  Mz %.2f N m  Rl %.4f m\n", static_cast<double>(t.fx_n),
              static_cast<double>(t.fy_n), static_cast<double>(t.mz_nm),
              static_cast<double>(t.rl_m));
  std::printf("contact table '%s' at y = 3 mm: status %s\n", r.pair ? r.pair : "(none)",
              tread::to_string(r.contact.status));
  std::printf("  r_left %.3f mm  r_right %.3f mm  delta_r %.3f mm\n",
              static_cast<double>(c.r_left_mm), static_cast<double>(c.r_right_mm),
              static_cast<double>(c.delta_r_mm));
  // Sane, not exact (tread's own tests check the numbers): a driving force and a side force below
  // the friction limit, wheel radii of a rail vehicle, a rolling-radius difference of a few tenths
  // of a millimetre.
  const float limit_n = 2.0F * t.fz_n;
  const bool tyre_sane = t.status == tread::Status::ok && t.fx_n > 0.0F && t.fx_n < limit_n &&
                         std::abs(t.fy_n) > 1.0F && std::abs(t.fy_n) < limit_n;
  const bool contact_sane = r.contact.ok() && c.r_left_mm > 300.0F && c.r_left_mm < 700.0F &&
                            std::abs(c.delta_r_mm) > 0.01F && std::abs(c.delta_r_mm) < 10.0F;
  const bool sane = tyre_sane && contact_sane;
  std::printf("%s\n", sane ? "consumer: sane" : "consumer: NOT sane");
  return sane ? 0 : 1;
}

#endif
