#include "step_timings.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "atomic_file.h"

namespace dp::io {

StepTiming table1_row(const StepReport& r, std::int64_t step, double time_s) {
  StepTiming t;
  t.step = step;
  t.time_s = time_s;
  t.dt_s = r.dt;
  t.ptcl_ms = 1e3 * (r.seconds_pressure + r.seconds_other);
  t.grid_ms = 1e3 * r.seconds_grid;
  t.neigh_ms = 1e3 * r.seconds_neighbours;
  t.heat_ms = 1e3 * r.seconds_heat;
  t.eva_ms = 1e3 * r.seconds_evaporation;
  t.pressure_iterations = r.pressure_iterations;
  t.density_error = r.density_error;
  t.air_iterations = r.air.projection_iterations;
  return t;
}

namespace {

constexpr const char* kTimingsHeader =
    "step,time_s,dt_ms,ptcl_ms,grid_ms,neigh_ms,heat_ms,eva_ms,pcisph_iterations,density_error,air_cg_iterations\n";

// One row of an earlier run's table; false when the line is not one.
bool parse_timing_row(const std::string& line, StepTiming& t) {
  long long step = 0;
  double dt_ms = 0;
  const int fields = std::sscanf(line.c_str(), "%lld,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%d,%lf,%d", &step, &t.time_s, &dt_ms, &t.ptcl_ms, &t.grid_ms,
                                 &t.neigh_ms, &t.heat_ms, &t.eva_ms, &t.pressure_iterations, &t.density_error, &t.air_iterations);
  t.step = step;
  t.dt_s = 1e-3 * dt_ms;
  return fields == 11;
}

}  // namespace

StepTimingsCsv::StepTimingsCsv(const std::filesystem::path& file) : file_(file), out_(file, std::ios::trunc) {
  if (!out_) throw std::runtime_error(file.string() + ": cannot write the timing table");
  out_ << kTimingsHeader;
}

StepTimingsCsv::StepTimingsCsv(const std::filesystem::path& file, std::int64_t last_step) : file_(file) {
  std::vector<std::string> kept;
  {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);  // header
    StepTiming t;
    while (std::getline(in, line))
      if (parse_timing_row(line, t) && t.step <= last_step) {
        rows_.push_back(t);
        kept.push_back(line);
      }
  }
  write_atomically(file, [&](std::ostream& out) {
    out << kTimingsHeader;
    for (const std::string& line : kept) out << line << "\n";
  });
  out_.open(file, std::ios::app);
  if (!out_) throw std::runtime_error(file.string() + ": cannot write the timing table");
}

void StepTimingsCsv::add(const StepTiming& t) {
  rows_.push_back(t);
  write_row(t);
}

void StepTimingsCsv::write_row(const StepTiming& t) {
  char line[256];
  std::snprintf(line, sizeof line, "%lld,%.9g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%d,%.6g,%d\n", static_cast<long long>(t.step), t.time_s,
                1e3 * t.dt_s, t.ptcl_ms, t.grid_ms, t.neigh_ms, t.heat_ms, t.eva_ms, t.pressure_iterations, t.density_error,
                t.air_iterations);
  out_ << line;
}

void StepTimingsCsv::flush() {
  out_.flush();
  if (!out_) throw std::runtime_error(file_.string() + ": writing the timing table failed");
}

namespace {

TimingSummary::Column summarise(const std::string& name, std::vector<double> v) {
  TimingSummary::Column c{name, 0, 0, 0};
  if (v.empty()) return c;
  double sum = 0;
  for (double x : v) sum += x;
  c.mean = sum / static_cast<double>(v.size());
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  c.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  c.max = v.back();
  return c;
}

}  // namespace

TimingSummary StepTimingsCsv::summary() const {
  TimingSummary s;
  s.steps = static_cast<std::int64_t>(rows_.size());
  const std::pair<const char*, std::function<double(const StepTiming&)>> columns[] = {
      {"Ptcl", [](const StepTiming& t) { return t.ptcl_ms; }},  {"Grid", [](const StepTiming& t) { return t.grid_ms; }},
      {"Neigh", [](const StepTiming& t) { return t.neigh_ms; }}, {"Heat", [](const StepTiming& t) { return t.heat_ms; }},
      {"Eva", [](const StepTiming& t) { return t.eva_ms; }},     {"dtau", [](const StepTiming& t) { return 1e3 * t.dt_s; }}};
  for (const auto& [name, value] : columns) {
    std::vector<double> v;
    v.reserve(rows_.size());
    for (const StepTiming& t : rows_) v.push_back(value(t));
    s.columns.push_back(summarise(name, std::move(v)));
  }
  return s;
}

void write_timing_summary(const std::filesystem::path& file, const TimingSummary& summary) {
  nlohmann::json j;
  j["steps"] = summary.steps;
  j["unit"] = "ms per step (dtau: ms)";
  for (const auto& c : summary.columns) j["columns"][c.name] = {{"mean", c.mean}, {"median", c.median}, {"max", c.max}};
  write_atomically(file, [&](std::ostream& out) { out << j.dump(2) << "\n"; });
}

std::string format_timing_summary(const TimingSummary& summary) {
  std::string text = "per-step times (ms) over " + std::to_string(summary.steps) + " steps\n          ";
  for (const auto& c : summary.columns) {
    char cell[16];
    std::snprintf(cell, sizeof cell, "%10s", c.name.c_str());
    text += cell;
  }
  using Statistic = double TimingSummary::Column::*;
  const std::pair<const char*, Statistic> rows[] = {{"mean", &TimingSummary::Column::mean},
                                                    {"median", &TimingSummary::Column::median},
                                                    {"max", &TimingSummary::Column::max}};
  for (const auto& [label, statistic] : rows) {
    char cell[16];
    std::snprintf(cell, sizeof cell, "\n%-10s", label);
    text += cell;
    for (const auto& c : summary.columns) {
      std::snprintf(cell, sizeof cell, "%10.3f", c.*statistic);
      text += cell;
    }
  }
  return text + "\n";
}

}  // namespace dp::io
