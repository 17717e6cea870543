#pragma once
// Cells of a surface that faces the camera far away, whose noise the frame's estimate misses.
// Depth noise moves points along their rays, so a cell's RMS about its plane is the noise along
// the rays times |cos| (between its normal and its ray). A tunnel's walls, seen at grazing
// incidence, show a fraction of it, and the frame's noise is estimated from them
// (CellGrid::noise_per_m2); a plate across the view shows all of it. 3.3 m before a
// diaphragm its cells measured 12 mm RMS and its 3x3 blocks 22-27 mm against a bound of 20 mm,
// and the plate made no plane.
#include <vector>

#include "core/planes/cell_fits.h"

namespace tunnelmap {

// The noise along the rays, sigma_z = c z^2: c is the lower quartile of RMS / (z^2 |cos|) over
// the cells whose own normal is known (quiet, standard error within 0.1 rad) and that face
// the camera enough to divide by (|cos| >= 0.3), from 1 m on, where the z^2 term outgrows the
// sensor's constant floor; 0 with fewer than 16 such cells. Needs the cells' quiet flags and
// their own normals' standard errors.
double axial_noise_coefficient(const CellGrid& grid, std::vector<double>& ratios);

// Makes planar each fitted cell that is not (a candidate), when the candidates in its 3x3
// block fit one plane that faces the camera enough for the noise along the rays to explain
// the cell's RMS and the block's (the bound and F test of smooth_cell_normals, with that noise
// at the block's facing). The block's normal is fitted without what that noise adds to the
// points' scatter (errors in variables): at 3.3 m the noise, 27 mm, is a fifth of the block's
// width, and the plain fit put the plate's normal across the rays. Run after the block normals.
void admit_cells_facing_the_camera(CellGrid& grid, double max_f);

}  // namespace tunnelmap
