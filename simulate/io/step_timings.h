#pragma once
// Per-step run times in the columns of the paper's Table 1, written as
// stats/timings.csv while the simulation runs and summarised at the end.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "simulation.h"

namespace dp::io {

// One row of the table. Paper Table 1: Ptcl = the SPH simulation (density,
// forces, pressure solve, integration), Grid = the air (Alg. 1 lines 7-11),
// Neigh = neighbourhood searches, Heat = heat transfer and interpolation,
// Eva = evaporation and condensation; all in ms of wall clock.
struct StepTiming {
  std::int64_t step = 0;
  double time_s = 0, dt_s = 0;
  double ptcl_ms = 0, grid_ms = 0, neigh_ms = 0, heat_ms = 0, eva_ms = 0;
  int pressure_iterations = 0;
  double density_error = 0;
  int air_iterations = 0;
};

StepTiming table1_row(const StepReport& report, std::int64_t step, double time_s);

// Mean, median and maximum of each timing column over the recorded steps.
struct TimingSummary {
  std::int64_t steps = 0;
  struct Column {
    std::string name;
    double mean = 0, median = 0, max = 0;
  };
  std::vector<Column> columns;  // Ptcl, Grid, Neigh, Heat, Eva (ms), dtau (ms)
};

class StepTimingsCsv {
 public:
  // Starts the file with its header, replacing an older one.
  explicit StepTimingsCsv(const std::filesystem::path& file);
  // Continues an existing table after a restart from a checkpoint at
  // `last_step`: its rows up to that step are kept (and summarised), later
  // ones, which the resumed run computes again, are dropped. A missing or
  // unreadable table starts afresh.
  StepTimingsCsv(const std::filesystem::path& file, std::int64_t last_step);
  void add(const StepTiming& row);
  // Makes the rows so far durable (called at every frame).
  void flush();
  TimingSummary summary() const;

 private:
  void write_row(const StepTiming& row);
  std::filesystem::path file_;
  std::ofstream out_;
  std::vector<StepTiming> rows_;
};

// The summary as JSON (stats/timings_summary.json) and as one table for
// the log, with the paper's column names.
void write_timing_summary(const std::filesystem::path& file, const TimingSummary& summary);
std::string format_timing_summary(const TimingSummary& summary);

}  // namespace dp::io
