// Exact overlap areas of a triangle with the cells of the grid, for the inner-fluid momentum
// I_T = sum_ij alpha_T(i,j) u_ij h^2 of docs/method.md §1.7 (variant K, step 1): the overlap of the
// (convex) triangle with a cell is the sum over its three edges of the signed area between the edge,
// held to the cell's row band, and the band's floor, within the cell's columns (the area of the
// triangle's vertical sections inside the cell; verification/oracles/clipped_cell_overlaps clips
// the square instead, and the test compares the two cell by cell). Summed over the triangles of a fan, the overlaps add up to the
// polygon's area to round-off, so the inner-fluid momentum is split between triangles without
// loss. Periodic directions wrap cell indices; in wall directions only cells inside the box count.
#pragma once
#include <array>
#include <vector>

#include "core/grid.hpp"

namespace ibms {

struct CellOverlap {
  int i = 0, j = 0;     // cell [-]
  double area = 0.0;    // overlap area [length^2 per unit depth]
};

// Appends the cells overlapped by triangle (a, b, c) (either orientation) with their overlap
// areas to `overlaps` (not cleared); cells with zero overlap are skipped.
void add_triangle_cell_overlaps(const Grid& grid, const std::array<double, 2>& a,
                                const std::array<double, 2>& b, const std::array<double, 2>& c,
                                std::vector<CellOverlap>& overlaps);

// Work arrays of add_polygon_cell_overlaps, grown to the largest bounding box seen.
struct PolygonOverlapWork {
  std::vector<double> partial, full;
};

// Appends the cells overlapped by the simple polygon `vertices` (either orientation) with their
// overlap areas to `overlaps` (not cleared), by the same edge shares as the triangles: an edge gives
// the cells of its columns that its y-range crosses their share, and every cell below it within
// those columns the full band, added once per column and carried down the column (a cell's cost is
// its bounding-box cell and the edges crossing it, not the edges times the cells). Equal to the sum
// of its fan triangles' overlaps to round-off (test_triangle_overlap); cells with an overlap below
// 1e-12 of a cell (the cancelled sums of cells outside) are skipped.
void add_polygon_cell_overlaps(const Grid& grid, const std::array<double, 2>* vertices, std::size_t n,
                               std::vector<CellOverlap>& overlaps, PolygonOverlapWork& work);

}  // namespace ibms
