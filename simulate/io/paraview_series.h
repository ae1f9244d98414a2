#pragma once
// A shot as a ParaView time series (dewpoint-simulate --paraview): each
// frame's particles as VTK XML PolyData (.vtp) with every per-particle
// attribute, its air grid as VTK XML ImageData (.vti) with the air VDB's
// fields, and one collection file (.pvd) that gives each frame its time.
// ParaView reads none of our PLY attributes beyond positions and no OpenVDB
// file, so these carry the same data in formats it opens natively.
// Written here, not through libvtk: the simulator travels to GPU machines as
// a bundle of the libraries it links (docs/gpu.md), and VTK's closure would
// outweigh the rest; the XML layout is small and VTK's readers check it
// (tests/cli/paraview_series_test.py). docs/file-formats.md, "ParaView time
// series".
#include <filesystem>
#include <string>
#include <vector>

#include "air/air_state.h"
#include "simulation.h"

namespace dp::io {

void write_particles_vtp(const std::filesystem::path& file, const ParticleSnapshot& particles, float radius);
void write_air_vti(const std::filesystem::path& file, const AirSnapshot& air);

// One frame of the collection: its time and the files written for it
// (relative to the collection's folder); an empty air file: no air.
struct SeriesFrame {
  double time_s;
  std::string particles_file, air_file;
};

// The collection: each frame's datasets at its time, the particles as part
// 0 and the air as part 1, so that ParaView shows them as one multiblock.
void write_pvd(const std::filesystem::path& file, const std::vector<SeriesFrame>& frames);

}  // namespace dp::io
