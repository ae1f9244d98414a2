#pragma once
// stats/ledger.csv (docs/file-formats.md): the water ledger of every written
// frame as a table, rewritten whole from the manifest's frames, so that it
// always agrees with the manifest (a resumed run included).
#include <filesystem>
#include <vector>

#include "frames.h"

namespace dp::io {

inline constexpr const char* kLedgerCsvHeader =
    "frame,time_s,step,liquid_kg,texels_kg,vapor_kg,in_kg,out_kg,drift_kg,relative_drift";

// Frames without a water ledger are left out.
void write_ledger_csv(const std::filesystem::path& file, const std::vector<FrameEntry>& frames);

}  // namespace dp::io
