#include "ledger_csv.h"

#include <cstdio>

#include "atomic_file.h"

namespace dp::io {

void write_ledger_csv(const std::filesystem::path& file, const std::vector<FrameEntry>& frames) {
  write_atomically(file, [&](std::ostream& out) {
    out << kLedgerCsvHeader << "\n";
    for (const FrameEntry& f : frames) {
      if (!f.water.is_object()) continue;
      const auto kg = [&](const char* key) { return f.water.value(key, 0.0); };
      // What crossed the scene's boundary: inflow cells (their gain may be
      // negative), open faces, and liquid that left the domain.
      const double in = kg("inflow_gain_kg") + kg("open_in_kg"), out_kg = kg("open_out_kg") + kg("liquid_out_kg");
      char line[400];
      // 17 significant digits: a double read back is the double written.
      std::snprintf(line, sizeof line, "%d,%.17g,%lld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", f.index, f.time_s,
                    static_cast<long long>(f.step), kg("liquid_kg"), kg("texels_kg"), kg("vapor_kg"), in, out_kg, kg("drift_kg"),
                    f.water.value("relative_drift", 0.0));
      out << line;
    }
  });
}

}  // namespace dp::io
