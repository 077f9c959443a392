// geocert's CGAL oracle: the C++ side of the cxx bridge declared in src/oracle/ffi.rs.
//
// Every function builds its own CGAL objects from doubles (Epeck objects are lazy
// and must not be shared across threads), runs one CGAL operation and returns the
// result's kind and coordinates:
//   * epeck_*      — Exact_predicates_exact_constructions_kernel, coordinates as
//                    canonical rational strings "p/q" (or "p") of CGAL::exact(x);
//   * epeck_*_f64  — the same Epeck computation, coordinates as doubles: the lazy
//                    interval approximation (force_exact = false) or to_double of
//                    the forced exact value (force_exact = true);
//   * epick_*      — Exact_predicates_inexact_constructions_kernel, doubles.
// Degenerate input (zero direction, zero normal, collinear plane vectors, a segment
// whose end points coincide, a closed range [lo, hi] with lo >= hi) throws std::invalid_argument with the message
// "geocert:<error kind>:<field>", which cxx turns into a Rust Err. So does any
// exception CGAL throws.
#pragma once
#include <array>

namespace geocert_oracle {

struct PlaneIn;
struct Two3;
struct Two2;
struct Linear3;
struct ExactOut;
struct FloatOut;
using Point3In = std::array<double, 3>;

ExactOut epeck_line_plane(const Two3 &line, const PlaneIn &plane);
ExactOut epeck_segment_plane(const Two3 &segment, const PlaneIn &plane);
ExactOut epeck_plane_plane(const PlaneIn &a, const PlaneIn &b);
ExactOut epeck_three_planes(const PlaneIn &a, const PlaneIn &b, const PlaneIn &c);
ExactOut epeck_project_point_line(const Point3In &point, const Two3 &line);
ExactOut epeck_project_point_plane(const Point3In &point, const PlaneIn &plane);
ExactOut epeck_lines_2d(const Two2 &a, const Two2 &b);
ExactOut epeck_segments_2d(const Two2 &a, const Two2 &b);
ExactOut epeck_line_line(const Linear3 &a, const Linear3 &b);

FloatOut epeck_line_plane_f64(bool force_exact, const Two3 &line, const PlaneIn &plane);
FloatOut epeck_segment_plane_f64(bool force_exact, const Two3 &segment, const PlaneIn &plane);
FloatOut epeck_plane_plane_f64(bool force_exact, const PlaneIn &a, const PlaneIn &b);
FloatOut epeck_three_planes_f64(bool force_exact, const PlaneIn &a, const PlaneIn &b,
                                const PlaneIn &c);
FloatOut epeck_project_point_line_f64(bool force_exact, const Point3In &point, const Two3 &line);
FloatOut epeck_project_point_plane_f64(bool force_exact, const Point3In &point,
                                       const PlaneIn &plane);
FloatOut epeck_lines_2d_f64(bool force_exact, const Two2 &a, const Two2 &b);
FloatOut epeck_segments_2d_f64(bool force_exact, const Two2 &a, const Two2 &b);
FloatOut epeck_line_line_f64(bool force_exact, const Linear3 &a, const Linear3 &b);

FloatOut epick_line_plane(const Two3 &line, const PlaneIn &plane);
FloatOut epick_segment_plane(const Two3 &segment, const PlaneIn &plane);
FloatOut epick_plane_plane(const PlaneIn &a, const PlaneIn &b);
FloatOut epick_three_planes(const PlaneIn &a, const PlaneIn &b, const PlaneIn &c);
FloatOut epick_project_point_line(const Point3In &point, const Two3 &line);
FloatOut epick_project_point_plane(const Point3In &point, const PlaneIn &plane);
FloatOut epick_lines_2d(const Two2 &a, const Two2 &b);
FloatOut epick_segments_2d(const Two2 &a, const Two2 &b);
FloatOut epick_line_line(const Linear3 &a, const Linear3 &b);

} // namespace geocert_oracle
