// What "standing" means in every demo, test and measurement of this repository: no body moved
// more than kStandingDriftMeters from where it started. Header only, no dependencies, so that
// the parity specs (which build their worlds as an app does, without the harness) share it.
#pragma once

namespace harness
{
/// A body that moved more than this from where it started has "fallen" (metres).
constexpr double kStandingDriftMeters = 0.01;
}  // namespace harness
