// Oracle for ibm/triangle_cell_overlap: the overlap of a triangle with each grid cell by clipping
// the cell square with the triangle's three half-planes (Sutherland-Hodgman) and taking the
// clipped polygon's shoelace area, over every cell of the triangle's bounding box (periodic
// directions wrap, wall directions keep the cells inside the box). Slow and independent of the
// solver's edge integrals.
#pragma once
#include <array>
#include <vector>

#include "core/grid.hpp"
#include "ibm/triangle_cell_overlap.hpp"

namespace ibms::oracle {

std::vector<CellOverlap> clipped_cell_overlaps(const Grid& grid, const std::array<double, 2>& a,
                                               const std::array<double, 2>& b, const std::array<double, 2>& c);

}  // namespace ibms::oracle
