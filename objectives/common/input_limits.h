#pragma once
// Input limits: the allowed range of every user input that more than one place checks (a file
// reader, a command-line option, an Options::IsValid), in one table, so a limit is changed once
// and every message quotes the same bounds. Readers turn a Limit into their own range type
// (files/json_fields.h: Range::Of; apps/cli_checks.h: CliRange).
// The table lives in objectives/common, the lowest layer with an IsValid that uses it
// (Fidelity::IsValid); calibrate, workflow, diagnose and apps include it from above.
//
//   if (!limits::kSizeScale.Contains(x))
//     error = "size_scale = ... is outside the allowed range " + limits::kSizeScale.Text();
#include "core/bodies/clump_shapes.h"
#include "core/limits/physical_limits.h"

namespace demcal::objectives::limits {

// The interval type and the scene's physical ranges live in the core (Scene::IsValid uses them):
// core/limits/physical_limits.h. They are part of this table.
using core::limits::Closed;
using core::limits::LeftOpen;
using core::limits::Limit;
using core::limits::Open;

// A run's fidelity (objectives/common/fidelity.h): experiment files, reproduce workflow files,
// Fidelity::IsValid. Never finer nor stiffer than the real particles.
inline constexpr Limit kSizeScale = Closed(1, 20);
inline constexpr Limit kStiffnessScale = LeftOpen(0, 1);
inline constexpr Limit kRayleighFraction = LeftOpen(0, 1);

// Replicates of an experiment or a calibration study (experiment and study files).
inline constexpr Limit kReplicates = Closed(1, 1000);
// Replicates per stage of `demcal reproduce` (workflow files: a stage runs many such heaps).
inline constexpr Limit kWorkflowReplicates = Closed(1, 100);

// The optimiser (calibrate/optimiser.h): study files, --max-evaluations of calibrate and
// diagnose, OptimiserOptions::IsValid.
inline constexpr Limit kMaxEvaluations = Closed(1, 100000);
inline constexpr Limit kBatchSize = Closed(1, 1024);
inline constexpr Limit kUnitTolerance = Open(0, 0.5);

// Cores for runs side by side (--threads of calibrate, diagnose and reproduce; 0: all).
inline constexpr Limit kThreads = Closed(0, 1024);

// Spheres per clump of an ellipsoid shape (core/bodies/clump_shapes.h): scene files, study
// files' clump_count.counts, workflow files' clump_counts.
inline constexpr Limit kClumpSpheres = Closed(1, core::kMaxEllipsoidSpheres);

// The discrepancy diagnosis (diagnose/loop/diagnosis.h): its command-line options and
// DiagnoseOptions::IsValid.
inline constexpr Limit kSignificance = Open(0, 0.5);
inline constexpr Limit kDiscrepancyFloor = Closed(0, 10);  // single-run scatters
inline constexpr Limit kDiagnoseRefits = Closed(1, 10);
inline constexpr Limit kDiagnoseMaxEffects = Closed(1, 6);
inline constexpr Limit kDiagnoseExtraRefits = Closed(0, 20);

// `demcal cohesion` (calibrate/cohesion_scaling.h): its options and CohesionInputs::IsValid.
inline constexpr Limit kCohesionGamma = LeftOpen(0, 100);     // J/m2
inline constexpr Limit kCohesionYoungs = LeftOpen(0, 1e13);   // Pa
inline constexpr Limit kCohesionPoisson = Open(-1, 0.5);
inline constexpr Limit kCohesionRadius = LeftOpen(0, 1);      // m
inline constexpr Limit kCohesionDensity = LeftOpen(0, 1e5);   // kg/m3
inline constexpr Limit kCohesionGravity = LeftOpen(0, 1e3);   // m/s2

// A measurement's uncertainty (the tidy table's column, a study's stated uncertainty): at least
// this fraction of its observable's physical span (calibrate/observable_registry.h). A residual
// is at most the span, so every χ² term ((simulated − measured) / u)² stays below 1e24 and the
// cost finite for any number of targets. No instrument resolves 1e-12 of a span (an angle to
// 1e-10 degree, a mass flow to 1 mg/s in the 1e6 kg/s span); a smaller value is a typing or unit
// mistake (1e-320 made the cost NaN).
inline constexpr double kMinUncertaintyFraction = 1e-12;

}  // namespace demcal::objectives::limits
