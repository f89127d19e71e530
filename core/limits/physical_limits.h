#pragma once
// Physical limits: the allowed range of every scene quantity that a reader, Scene::IsValid or a
// clump builder checks, each with where its bound comes from. They are the core's part of the
// one table of input limits (objectives/common/input_limits.h includes this file, so every
// layer above quotes the same bounds); the core holds them because Scene::IsValid, the lowest
// user, cannot include upwards. A bound here is a statement about the physics or about what the
// engine can compute meaningfully, never a value tuned to a particular bad input.
//
// Derived checks (Scene::IsValid, core/scene/scene_validation.cc) combine these with the time
// step: see kMaxStepTravelRadii.
//
//   if (!limits::kGravity.Contains(Norm(g))) error = "... " + limits::kGravity.Text();
#include <string>

namespace demcal::core::limits {

// An interval of allowed values; open ends exclude the bound.
struct Limit {
  double lo = 0, hi = 0;
  bool lo_open = false, hi_open = false;
  // False for NaN.
  constexpr bool Contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string Text() const;  // "[1, 20]", "(0, 1]" (numbers to 6 significant digits)
};

constexpr Limit Closed(double lo, double hi) { return {lo, hi, false, false}; }
constexpr Limit LeftOpen(double lo, double hi) { return {lo, hi, true, false}; }
constexpr Limit Open(double lo, double hi) { return {lo, hi, true, true}; }

// --- materials and pair interactions -------------------------------------------------------
// Young's (and shear) modulus: from soft hydrogels (~1e3 Pa) to above diamond (1.2e12 Pa), and
// to a quasi-rigid wall material, modelled a thousandfold stiffer than steel or alumina (the
// Chung & Ooi impact benchmarks: up to 3.8e14 Pa).
inline constexpr Limit kYoungsModulus = Closed(1e3, 1e16);  // Pa
// The thermodynamic bounds of an isotropic elastic solid.
inline constexpr Limit kPoissonRatio = Open(-1, 0.5);
// A particle material's density: from the lightest aerogels (~1 kg/m3) to above osmium
// (22,590 kg/m3), with room for made-up test materials. Wall materials may leave it 0 (unused).
inline constexpr Limit kParticleDensity = Closed(1, 1e5);  // kg/m3
// Coulomb and rolling friction coefficients: 10 is a contact that never slides (or rolls);
// larger values are the same physics.
inline constexpr Limit kFriction = Closed(0, 10);
inline constexpr Limit kRestitution = LeftOpen(0, 1);
// Interfacial energy Γ: real adhesive contacts are below ~1 J/m2; the bound leaves three decades
// for Γ carried to a softer simulation stiffness by the Cohesion-number scaling.
inline constexpr Limit kInterfacialEnergy = Closed(0, 1e3);  // J/m2
// sjkr cohesion energy density k (J/m³ = Pa: a cohesive stress over the contact circle). LIGGGHTS
// users set 1e3 to 1e6; a cohesive stress above 1 GPa would exceed the strength of any solid
// bridge between grains, so the bound still leaves three decades above the largest in use.
inline constexpr Limit kCohesionEnergyDensity = Closed(0, 1e9);  // J/m3
// EPSD rolling damping ratio (Ai et al. 2011): a fraction of critical damping.
inline constexpr Limit kDampingRatio = Closed(0, 1);

// --- particles and clumps --------------------------------------------------------------------
// Sphere diameters: below 100 nm Brownian motion and van der Waals forces the engine does not
// model dominate; 10 m is beyond any boulder a DEM scene would hold.
inline constexpr Limit kDiameter = Closed(1e-7, 10);  // m
// Clump ellipsoid semi-axes and explicit member spheres are in any one length unit (the engine
// scales the shape to the species' diameter): nine decades either side of 1 cover a grain in
// metres and a boulder in micrometres, and keep a·b·c and the inertia sums finite.
inline constexpr Limit kClumpLength = Closed(1e-9, 1e9);
// Aspect ratio a/c of a clump ellipsoid: the builder chains at most 5 spheres along the long
// axis (core/bodies/clump_shapes.h); beyond 10:1 they are detached beads on a line, not the
// ellipsoid, and a rod or fibre needs another model.
inline constexpr Limit kClumpAspectRatio = Closed(1, 10);

// --- geometry and motion ---------------------------------------------------------------------
// Coordinates of the domain, walls, particles, regions and sinks: 1000 km, far beyond any
// apparatus; the same bound as STL vertices (core/walls/mesh_io.cc).
inline constexpr Limit kCoordinate = Closed(-1e6, 1e6);  // m
// Radii of cylinder and cone walls: a 1 km silo is beyond any apparatus.
inline constexpr Limit kWallRadius = Closed(0, 1e3);  // m
// |g|: Earth's 9.81 m/s2 to beyond the largest geotechnical centrifuges (a few hundred g) and
// high-g granulators; more is a unit mistake.
inline constexpr Limit kGravity = Closed(0, 1e4);  // m/s2
// |v| of a particle, a fill, a factory's insertion velocity or its region, or a wall: granular
// flows and impacts stay well below the speed of sound in air (343 m/s).
inline constexpr Limit kSpeed = Closed(0, 1e3);  // m/s
// |ω| of a particle: a 2 mm sphere at 1e6 rad/s has a surface speed of 1000 m/s (kSpeed).
inline constexpr Limit kAngularSpeed = Closed(0, 1e6);  // rad/s
// Derived (Scene::IsValid): in one time step no particle or wall may travel more than this many
// radii of the smallest sphere, with speeds taken at their largest before the run starts (the
// initial speed plus a free fall through the domain along gravity). Beyond one radius a sphere
// can pass through a partner or a wall between two force evaluations (tunnelling); the Rayleigh
// time step resolves contacts only at speeds far below that. A step the scene insists on
// (time.force_timestep) is exempt, as it is from the Rayleigh-time check.
inline constexpr double kMaxStepTravelRadii = 1;

// --- factories -------------------------------------------------------------------------------
// Mass rate: 1000 kg/s (3600 t/h) is the largest bulk conveyors; a DEM feed is far below.
inline constexpr Limit kMassRate = LeftOpen(0, 1e3);  // kg/s

}  // namespace demcal::core::limits
