#include "objectives/metrics/heap_bins.h"

#include <algorithm>
#include <cmath>

namespace demcal::objectives {
namespace {

// The value after setting aside the `skip` smallest (clamped to the size); `values` is reordered.
double NthSmallest(std::vector<double>& values, int skip) {
  const auto rank = std::min(static_cast<size_t>(std::max(skip, 0)), values.size() - 1);
  std::nth_element(values.begin(), values.begin() + static_cast<long>(rank), values.end());
  return values[rank];
}

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

// Index of the bin holding `value` among `count` equal bins starting at `lo` with width `w`;
// `value` == the far end belongs to the last bin; −1 outside.
int EqualBinOf(double value, double lo, double w, int count) {
  const double t = (value - lo) / w;
  if (!(t >= 0) || t > count) return -1;
  return std::min(static_cast<int>(t), count - 1);
}

}  // namespace

std::optional<HeapExtent> EstimateHeapExtent(const Snapshot& snapshot, std::string* error,
                                             int outlier_count) {
  if (snapshot.grains.empty()) {
    Fail(error, "heap extent: the snapshot holds no grains");
    return std::nullopt;
  }
  double bottom = snapshot.grains.front().position_m.z - snapshot.grains.front().radius_m;
  double radius_sum = 0;
  std::vector<double> minus_top;  // −(z + r), so the highest tops are the smallest values
  for (const Grain& g : snapshot.grains) {
    bottom = std::min(bottom, g.position_m.z - g.radius_m);
    radius_sum += g.radius_m;
    minus_top.push_back(-(g.position_m.z + g.radius_m));
  }
  const double base_band = 4 * radius_sum / static_cast<double>(snapshot.grains.size());
  std::vector<double> left, minus_right;
  for (const Grain& g : snapshot.grains) {
    if (g.position_m.z - g.radius_m > bottom + base_band) continue;
    left.push_back(g.position_m.x - g.radius_m);
    minus_right.push_back(-(g.position_m.x + g.radius_m));
  }
  HeapExtent extent;
  extent.x_left_m = NthSmallest(left, outlier_count);
  extent.x_right_m = -NthSmallest(minus_right, outlier_count);
  extent.z_base_m = bottom;
  extent.height_m = -NthSmallest(minus_top, outlier_count) - bottom;
  return extent;
}

bool HeapBinOptions::IsValid(std::string* error) const {
  if (row_bins.empty()) return Fail(error, "heap bins: row_bins is empty");
  for (size_t k = 0; k < row_bins.size(); ++k) {
    if (row_bins[k] < 1) return Fail(error, "heap bins: row_bins[" + std::to_string(k) + "] < 1");
    if (!rectangular && row_bins[k] > row_bins[0])
      return Fail(error, "heap bins: triangle row " + std::to_string(k) +
                             " has more bins than the bottom row");
  }
  if (layers < 1) return Fail(error, "heap bins: layers must be >= 1");
  if (!(y_max_m > y_min_m)) return Fail(error, "heap bins: y_max_m must exceed y_min_m");
  return true;
}

std::optional<HeapBinGrid> HeapBinGrid::Create(const HeapBinOptions& options,
                                               const HeapExtent& extent, std::string* error) {
  if (!options.IsValid(error)) return std::nullopt;
  const double width = extent.x_right_m - extent.x_left_m;
  if (!(width > 0) || !(extent.height_m > 0) || !std::isfinite(width + extent.height_m)) {
    Fail(error, "heap bins: the heap extent needs a positive width and height");
    return std::nullopt;
  }
  HeapBinGrid grid;
  grid.extent_ = extent;
  grid.layers_ = options.layers;
  grid.y_min_m_ = options.y_min_m;
  grid.y_max_m_ = options.y_max_m;
  const int rows = static_cast<int>(options.row_bins.size());
  grid.row_height_m_ = extent.height_m / rows;
  const double bottom_bin_width = width / options.row_bins[0];
  for (int k = 0; k < rows; ++k) {
    const int n = options.row_bins[k];
    const double w = options.rectangular ? width / n : bottom_bin_width;
    const double start = extent.x_left_m + (width - n * w) / 2;
    grid.row_first_bin_.push_back(grid.face_bin_count());
    for (int c = 0; c < n; ++c) {
      grid.face_bins_.push_back({k, c, start + c * w, start + (c + 1) * w,
                                 extent.z_base_m + k * grid.row_height_m_,
                                 extent.z_base_m + (k + 1) * grid.row_height_m_});
    }
  }
  return grid;
}

int HeapBinGrid::FaceBinOf(double x_m, double z_m) const {
  const int rows = static_cast<int>(row_first_bin_.size());
  const int row = EqualBinOf(z_m, extent_.z_base_m, row_height_m_, rows);
  if (row < 0) return -1;
  const FaceBin& first = face_bins_[row_first_bin_[row]];
  const int n = (row + 1 < rows ? row_first_bin_[row + 1] : face_bin_count()) - row_first_bin_[row];
  const int col = EqualBinOf(x_m, first.x_min_m, first.x_max_m - first.x_min_m, n);
  return col < 0 ? -1 : row_first_bin_[row] + col;
}

int HeapBinGrid::LayerOf(double y_m) const {
  return EqualBinOf(y_m, y_min_m_, LayerThicknessM(), layers_);
}

}  // namespace demcal::objectives
