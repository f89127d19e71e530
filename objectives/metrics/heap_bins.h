#pragma once
// HeapBinGrid: the sampling bins of the segregation heap (Alizadeh et al. 2018, section 2.6 and
// Fig. 8). The heap face (x width, z height) is cut into rows of bins; the box depth (y) into
// equal layers. A grain belongs to the bin that holds its centre.
//
// Default face grid: a triangle of rows of 6, 5, 4, 3, 2, 1 bins following the heap (21 bins).
// With the heap's base [x_left, x_right] at z_base and its height H, row k (k = 0 at the bottom)
// spans z in [z_base + k H/R, z_base + (k+1) H/R] (R = number of rows) and holds n_k bins of width
// w = (x_right − x_left)/n_0, centred on the heap: it starts at x_left + (n_0 − n_k) w/2, i.e. at
// x_left + k w/2 for the default rows. A triangular heap lies wholly inside this staircase; the
// corner bins along the flanks are only partly filled, as in the paper. The rectangular option
// spans every row over the full base width.
//
// Depth: `layers` equal slabs between the box's y_min (front face, layer 0) and y_max (back face,
// layer layers−1). The paper's box is 16 mm deep, cut into 8 layers of 2 mm.
//
// Units SI (m). Immutable after Create; thread-safe to share. Usage:
//   HeapBinOptions o;  o.y_min_m = 0;  o.y_max_m = 0.016;
//   auto grid = HeapBinGrid::Create(o, EstimateHeapExtent(snapshot), &error);
//   const BinIndex bin = grid->Locate(grain.position_m);  // bin.face < 0: outside every bin
#include <optional>
#include <string>
#include <vector>

#include "objectives/common/snapshot.h"

namespace demcal::objectives {

// The heap's base width and height in the x–z plane.
struct HeapExtent {
  double x_left_m = 0;
  double x_right_m = 0;
  double z_base_m = 0;
  double height_m = 0;
};

// The heap extent from the grains, robust to a few stray grains: z_base is the lowest grain
// bottom (z − r; the base is flat); x_left/x_right are the extreme x ∓ r of the grains lying on
// the base (bottom within two mean diameters of z_base), and the top is the highest z + r, each
// after setting aside the `outlier_count` most extreme grains (so a toe or apex is not cut as a
// quantile would cut it). Returns nullopt (with a message) without grains.
std::optional<HeapExtent> EstimateHeapExtent(const Snapshot& snapshot, std::string* error,
                                             int outlier_count = 3);

struct HeapBinOptions {
  // Bins per row, bottom row first. The paper's Fig. 8: {6, 5, 4, 3, 2, 1}.
  std::vector<int> row_bins = {6, 5, 4, 3, 2, 1};
  // false: each row centred on the heap, bins of the bottom row's width (staircase triangle);
  // true: each row spans the full base width with equal bins.
  bool rectangular = false;
  // Equal slabs through the depth; the paper uses 8 layers of 2 mm.
  int layers = 8;
  // The box's depth extent: front face (layer 0) at y_min, back face at y_max.
  double y_min_m = 0;
  double y_max_m = 0.016;

  bool IsValid(std::string* error) const;
};

// One bin of the face grid, its rectangle in the x–z plane.
struct FaceBin {
  int row = 0;  // 0 = bottom row
  int col = 0;  // 0 = leftmost bin of its row
  double x_min_m = 0, x_max_m = 0;
  double z_min_m = 0, z_max_m = 0;
};

// Where a point falls: face bin index (into HeapBinGrid::face_bins) and layer; −1 when outside.
struct BinIndex {
  int face = -1;
  int layer = -1;
  bool Inside() const { return face >= 0 && layer >= 0; }
};

class HeapBinGrid {
 public:
  static std::optional<HeapBinGrid> Create(const HeapBinOptions& options, const HeapExtent& extent,
                                           std::string* error);

  const std::vector<FaceBin>& face_bins() const { return face_bins_; }
  int face_bin_count() const { return static_cast<int>(face_bins_.size()); }
  int layers() const { return layers_; }
  double y_min_m() const { return y_min_m_; }
  double y_max_m() const { return y_max_m_; }
  double LayerThicknessM() const { return (y_max_m_ - y_min_m_) / layers_; }
  const HeapExtent& extent() const { return extent_; }

  // Face bin of (x, z), or −1 outside every bin. Bin edges are half-open [min, max) except the
  // top of the top row and the right end of each row, which are closed.
  int FaceBinOf(double x_m, double z_m) const;
  // Layer of a depth coordinate y, or −1 outside [y_min, y_max].
  int LayerOf(double y_m) const;
  BinIndex Locate(const Vec3& position_m) const {
    return {FaceBinOf(position_m.x, position_m.z), LayerOf(position_m.y)};
  }

 private:
  std::vector<FaceBin> face_bins_;
  std::vector<int> row_first_bin_;  // index of each row's first bin in face_bins_
  HeapExtent extent_;
  double row_height_m_ = 0;
  int layers_ = 0;
  double y_min_m_ = 0, y_max_m_ = 0;
};

}  // namespace demcal::objectives
