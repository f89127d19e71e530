#pragma once
// Pictures of a measured heap for users to check the repose-angle measurement by eye: the
// surface profile (cell tops, surface_profile.h), the height window and every fitted flank line
// with its angle. Lengths drawn in mm, both axes at the same scale so the slopes look true.
//
//   const ReposeAngle a = MeasureSlotHeapAngle(snap, options);
//   WriteSvg(dir + "/heap_profile.svg", SlotHeapProfilePlot(snap, a, options), &error);
#include "objectives/metrics/repose_angle.h"
#include "objectives/report/svg_plot.h"

namespace demcal::objectives {

// x [mm] against z [mm]; left and right flank lines.
SvgPlot SlotHeapProfilePlot(const Snapshot& snapshot, const ReposeAngle& angle,
                            const ReposeAngleOptions& options);

// Distance to the axis r [mm] against z [mm]; all sectors superposed, one line per sector.
SvgPlot ConicalHeapProfilePlot(const Snapshot& snapshot, Vec3 axis_point_m,
                               const ReposeAngle& angle, const ReposeAngleOptions& options);

}  // namespace demcal::objectives
