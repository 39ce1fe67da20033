#pragma once
/// The results the io tests write, and the closed-form values in them (the Python reader
/// tests in tests/io/*.py use the same formulas).
#include <filesystem>
#include <string>
#include <vector>

#include "io/results_writer.hpp"
#include "model/model.hpp"

namespace inpact::test {

/// U_c of node row n in global frame k: 0.001 (k+1)(n+1) + 0.1 c.
/// One .sta row of step 1 whose total and step time are both `time`.
io::StatusRow status_row(int inc, int att, bool cut, int severe, int equil, double time, double dt, int aug);

double u_value(int k, std::size_t node_row, int c);
/// RF_c of node row n in frame k: -(k+1)(n+1) - 10 c (only node rows 0..3, not in frame 3).
double rf_value(int k, std::size_t node_row, int c);
/// S_c at location i (element-label-ordered integration points) of frame k: 100 k + 10 c + i.
double s_value(int k, std::size_t loc, int c);
/// CPRESS at slave node j of frame k: 1000 (k+1) + j.
double cpress_value(int k, std::size_t j);

/// The frames of the three-body job: global frame k of `step` (0: Load, 1: Unload).
io::Frame three_body_frame(const model::Model& model, int k);
/// Writes the three-body job (kThreeBodyDeck): steps Load (frames 0, 1) and Unload (frames 2, 3),
/// status rows, COMPLETED.
void write_three_body_job(const std::filesystem::path& h5, const model::Model& model);

/// A deck with one element of each VTK cell type inpact writes (C3D8 C3D20 C3D4 C3D10 C3D6
/// CPS4 CPS8 CPS3 CPS6), nodes at their reference positions, apart from each other.
/// `only`: just these types (e.g. {"C3D20"}); empty: all of them.
std::string all_types_deck(const std::vector<std::string>& only = {});
/// One step, two frames: U = 0.01 (k+1) × coordinates, S at the centroid with S11 = element row + 1.
void write_all_types_job(const std::filesystem::path& h5, const model::Model& model);

}  // namespace inpact::test
