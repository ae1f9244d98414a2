#pragma once
// The water ledger (DESIGN §6): where the scene's water is, in kg, and how
// far the stores' sum has drifted from what the start and the air's open
// boundaries and inflows say it should be.
//
// Units: liquid particles hold integer mass units (2^24 per particle),
// texels integer texel units (2^32 per mass unit); every transfer between
// liquid, texels and air is a whole number of texel units, counted exactly
// (liquid_to_air, texels_to_air). Only the air's vapor is a double field
// (its conservative transport needs real-valued fluxes), so the drift is the
// rounding of the vapor field's updates: ~1e-16 of a cell's vapor per
// update, summed over cells and steps.
namespace dp {

struct WaterLedger {
  double liquid_kg = 0, texel_kg = 0, vapor_kg = 0;
  double initial_kg = 0;      // liquid + texels + vapor at the start
  double inflow_gain_kg = 0;  // vapor set by inflow cells (may be negative)
  double open_in_kg = 0, open_out_kg = 0;  // vapor through open domain faces
  double liquid_to_air_kg = 0, texels_to_air_kg = 0;  // exchanged so far (exact units, shown in kg)
  double texels_to_liquid_kg = 0;                      // emitted particles (Sec. 6.2)
  double liquid_out_kg = 0;  // liquid particles that left the domain (DomainLeaving::Remove)

  double total_kg() const { return liquid_kg + texel_kg + vapor_kg; }
  double expected_kg() const { return initial_kg + inflow_gain_kg + open_in_kg - open_out_kg - liquid_out_kg; }
  double drift_kg() const { return total_kg() - expected_kg(); }
  double relative_drift() const { return expected_kg() != 0 ? drift_kg() / expected_kg() : drift_kg(); }
};

}  // namespace dp
