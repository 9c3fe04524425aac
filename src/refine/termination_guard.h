// The guard that makes refinement stop for any angle bound in [0, 60) degrees, beyond the
// Terminator's proven range (Sec. 6.3 guarantees termination, but bounds above about 34 degrees
// are not proven at all and can refine forever, Sec. 7.3, Fig. 37).
//
// It is the "sure-fire" rule of Sec. 6.2 with one floor for the whole run: no vertex is inserted
// whose insertion radius (the length of the shortest edge it would create) is below
// 2^-kGuardOctaves times the smallest feature size estimate f of the input. Each input vertex u has
// f(u) = the shortest edge at u in the initial triangulation, or the distance from u to a
// subsegment across one of its triangles if that is shorter (both upper bounds on lfs(u)). No edge
// shorter than the floor is ever created; a constrained Delaunay triangulation joins each vertex to
// its nearest visible neighbour, so vertices stay that far apart and only finitely many fit in the
// domain. Meshes within the proven range never come near the floor; size bounds lower it (a user who
// asks for area A gets edges down to sqrt(A) 2^-kGuardOctaves), and a triangle over its size bound
// is split under the precision floor alone (Terminator::floor_for), so the guard never blocks size
// refinement. (A per-vertex floor from the 1-Lipschitz extension of f was tried and refused
// ordinary insertions far from the input vertices, where that extension overestimates lfs.)
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/mesh_bounds.h"
#include "mesh/mesh.h"

namespace deltri {

inline constexpr int kGuardOctaves = 5;

// f(u) for every vertex of the initial mesh (HUGE_VAL for a vertex in no triangle).
std::vector<double> initial_feature_sizes(const Mesh& mesh);

// The smallest angle (radians) between two subsegments that meet at a vertex, measured inside the
// triangulation; HUGE_VAL if no two meet. Near an input angle phi the Terminator itself makes
// edges shorter than the features by about sin(phi / 2) (Sec. 6, Theorem 12), so the floor is
// scaled by angle_scale(phi) = min(1, 2 sin(phi / 2)): 1 from 60 degrees up. VVingerfly's
// test.poly, whose segments cross at 2e-6 radians, kept 222 triangles under -q30 with the floor
// unscaled and 45 (all at the then precision floor of 2^-36) with it scaled, and none since the
// floor is a quarter ulp.
// The scaling applies up to kCascadeAngleDeg (geometry/mesh_bounds.h): above it refinement can
// cascade (Sec. 7.3) and the unscaled floor stops it sooner (fan120 at -q40: 173,577 triangles left in 0.86 s unscaled,
// 302,722 in 1.22 s scaled, both at the Steiner cap).
double smallest_input_angle(const Mesh& mesh);
double angle_scale(double angle);

// The paper's proven range, where the guard takes no decision: every angle between two input
// segments 60 degrees or more (smallest_input_angle; within a relative 1e-9, since an equilateral
// corner written in doubles measures 60 degrees give or take 1e-15) and an angle bound at most
// the one the paper proves for the way subsegments are split: arcsin(1 / (2B)) for the smallest
// ratio bound B whose flow graph has no cycle below one. Diametral circles (Ruppert, Sec. 3.3,
// Fig. 14): B = sqrt 2, 20.70 degrees. Diametral lenses (the Ruppert-Chew hybrid of Sec. 6.4,
// r_v >= (sqrt 3 / 2) r_p): B = 2 / sqrt 3, 25.65 degrees. Chew's second algorithm (Sec. 4.2,
// Lemma 5, Fig. 17): B = sqrt 5 / 2, 26.56 degrees. There refinement ends with no edge shorter
// than a constant fraction of lfs_min, the number of vertices within a constant of the integral
// of 1 / lfs^2 (Sec. 4.3), so neither the feature floor nor the Steiner cap can stop refinement
// that the theorems say ends at the bound, and the guard is off; only the memory budget and the
// precision of doubles remain (docs/refinement.md, "What is proven"). -Y/-YY, Sec. 7.2's interior
// bound, Sec. 7.3's range-restricted splitting and corner-lopping are outside it (their callers
// keep the guard).
// The relative slack of "60 degrees or more" here and in the sure-fire rule's test
// (Terminator::meets_at_small_angle).
inline constexpr double kSixtySlack = 1e-9;
enum class SplitRule : std::uint8_t { DiametralCircles, DiametralLenses, Chew };
double proven_angle_deg(SplitRule rule);
bool within_proven_range(double smallest_input_angle, double angle_bound_deg, SplitRule rule);

// No edge shorter than a quarter of an ulp of the coordinates where it lies: 2^-kPrecisionOctaves
// of the larger coordinate, between an eighth and a quarter of its ulp, a positive length wherever
// a coordinate is not zero. Below kBottomScaleUlps (refine/bottom_scale.h) Steiner points and
// split points are chosen among the doubles near the ideal ones, so that inputs with vertices an
// ulp apart (robustness tests of other triangulators) are meshed down to that scale; a point can
// only go where a double is, so the floor itself only keeps insertions off existing vertices. The
// floor is local: a hole 2e-6 wide at the origin of a square 2e6 wide is meshed at its own scale.
inline constexpr int kPrecisionOctaves = 54;
double precision_floor_at(const Point& p);
// The coarse floor, 2^-36 relative (about 2^16 ulps), where the bottom scale is not meshed. It applies
// everywhere when the initial mesh has an edge that no double can give a good triangle
// (hopeless_edge in geometry/lattice.h): the bound cannot be met there, and grading the mesh down
// to the ulp scale at every other close pair would cost dozens of triangles per octave for
// nothing (robustness2.node at -pq30: 1,030,697 triangles in 3.4 s, against 6,910 in 0.03 s).
inline constexpr int kCoarsePrecisionOctaves = 36;

// The edge-length floor for a smallest feature estimate `feature`; size_floor (<= 0: none) is the
// edge length a size bound asks for.
double guard_floor(double feature, double size_floor);

// Ruppert's and Chew's algorithms and range-restricted splitting also refuse subsegment splits by
// Sec. 6.2's sure-fire rule where two segments meet at under 60 degrees: no split with a smaller
// insertion radius than its ancestor on the other segment (Terminator::refused_by_sure_fire_rule).
// Any floor leaves about ln(R / r) / phi coupled splits between segments at an angle phi, and
// VVingerfly's test.poly (phi = 2e-6) ran until the memory was gone under Ruppert's algorithm.

// The cap on Steiner points: the last line of defence against refinement that runs away.
//
// What a good mesh needs grows with the integral of 1/lfs^2 over the domain (Sec. 3.3 and 4.3,
// size optimality), not with the number of input vertices: a rectangle 1 x 1e-6 has four vertices
// and needs two million triangles at -q30. feature_work() estimates that integral from the initial
// triangulation (one unit is about one triangle of a quality mesh), and the cap is
// kCapPerWork Steiner points per unit, plus kCapPerVertex per vertex, plus four times the
// triangles the size bounds ask for (triangles_wanted). On the corpus and the benchmarks a mesh at
// -q34 has at most 4.2 triangles per unit of work (kevinsudo's A.poly, long strips 1,000 wide and
// 200,000 long), 0.1-1.2 elsewhere, so the cap is 15 times what the worst of them needs: it does not
// stop refinement that makes progress, and it stops runaway refinement long before the machine's
// memory is gone. Above kCascadeAngleDeg the cap is tighter (refine/refine.cpp: the mesh is first
// refined to kCascadeAngleDeg, then at most kCascadeAllowance Steiner points per vertex of that
// mesh are added), and every cap is clamped to the memory budget (RefineOptions::memory_budget).
inline constexpr double kCapPerWork = 32.0;
inline constexpr std::uint64_t kCapPerVertex = 64;
inline constexpr double kCascadeAllowance = 2.0;
// Bytes a Steiner point costs at the peak, with its two triangles (at most 86 bytes a triangle on the
// 45x45 holes, docs/benchmarks.md), its queue entries and the vertex: a generous figure, since the
// budget only has to keep deltri from growing until the kernel kills it.
inline constexpr double kBytesPerSteiner = 256.0;
inline constexpr double kBytesPerTriangle = kBytesPerSteiner / 2.0;

// The estimate of the integral of 1/lfs^2 over the domain, in triangles: each triangle adds its
// area over s^2, s its smallest altitude or the smallest feature size f of its corners, whichever
// is larger (a thin triangle between two segments is as wide as the strip); each edge adds half
// its length over the distance across it (a strip's neighbours grade down to its width); each
// vertex adds log2(1 + longest edge / f), the octaves the mesh grades over around it.
// `features`: initial_feature_sizes(mesh), when the caller has it already.
double feature_work(const Mesh& mesh);
double feature_work(const Mesh& mesh, const std::vector<double>& features);

std::uint64_t steiner_cap(const Mesh& mesh, const SizeBounds& bounds);
std::uint64_t steiner_cap(const Mesh& mesh, const SizeBounds& bounds, const std::vector<double>& features);
// The Steiner points that fit in `memory_budget` bytes beside a mesh of `triangle_slots` slots
// (UINT64_MAX for a budget of 0: none).
std::uint64_t memory_cap(std::uint64_t triangle_slots, double memory_budget);

// Where the budget is to be asked of the machine (RefineOptions::probe_memory), a run that starts
// from fewer than kProbeAfterSlots triangle slots asks only once it has placed kProbeAfterSteiner
// Steiner points, and size bounds are measured against it only when they ask for more than
// kProbeAfterBytes: a small run makes none of the system calls (issue 45). Its cap is then the one
// the budget would have set from the start; what a run may place before it asks (16 MiB at
// kBytesPerSteiner, beside a mesh of at most 8 MiB) is under any machine's budget.
inline constexpr std::uint64_t kProbeAfterSlots = 65536;
inline constexpr std::uint64_t kProbeAfterSteiner = 65536;
inline constexpr double kProbeAfterBytes = kBytesPerSteiner * kProbeAfterSteiner;
// The number of triangles the size bounds ask for (0 without size bounds), as in steiner_cap.
double triangles_wanted(const Mesh& mesh, const SizeBounds& bounds);

}  // namespace deltri
