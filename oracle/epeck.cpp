// The oracle's Epeck half: CGAL's exact-constructions kernel, the reference.
// Results as exact rationals (epeck_*) or as doubles (epeck_*_f64, for benchmarks).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "geocert/oracle/ops.h"

namespace geocert_oracle {

using K = CGAL::Exact_predicates_exact_constructions_kernel;

ExactOut epeck_line_plane(const Two3 &line, const PlaneIn &plane) {
  return ops::exact(ops::line_plane<K>(line, plane));
}
ExactOut epeck_segment_plane(const Two3 &segment, const PlaneIn &plane) {
  return ops::exact(ops::segment_plane<K>(segment, plane));
}
ExactOut epeck_plane_plane(const PlaneIn &a, const PlaneIn &b) {
  return ops::exact(ops::plane_plane<K>(a, b));
}
ExactOut epeck_three_planes(const PlaneIn &a, const PlaneIn &b, const PlaneIn &c) {
  return ops::exact(ops::three_planes<K>(a, b, c));
}
ExactOut epeck_project_point_line(const Point3In &point, const Two3 &line) {
  return ops::exact(ops::project_point_line<K>(point, line));
}
ExactOut epeck_project_point_plane(const Point3In &point, const PlaneIn &plane) {
  return ops::exact(ops::project_point_plane<K>(point, plane));
}
ExactOut epeck_lines_2d(const Two2 &a, const Two2 &b) {
  return ops::exact(ops::lines_2d<K>(a, b));
}
ExactOut epeck_segments_2d(const Two2 &a, const Two2 &b) {
  return ops::exact(ops::segments_2d<K>(a, b));
}
ExactOut epeck_line_line(const Linear3 &a, const Linear3 &b) {
  ops::ExactSink s;
  ops::line_line<K>(s, a, b);
  return std::move(s.out);
}

FloatOut epeck_line_plane_f64(bool force_exact, const Two3 &line, const PlaneIn &plane) {
  return ops::to_f64(force_exact, ops::line_plane<K>(line, plane));
}
FloatOut epeck_segment_plane_f64(bool force_exact, const Two3 &segment, const PlaneIn &plane) {
  return ops::to_f64(force_exact, ops::segment_plane<K>(segment, plane));
}
FloatOut epeck_plane_plane_f64(bool force_exact, const PlaneIn &a, const PlaneIn &b) {
  return ops::to_f64(force_exact, ops::plane_plane<K>(a, b));
}
FloatOut epeck_three_planes_f64(bool force_exact, const PlaneIn &a, const PlaneIn &b,
                                const PlaneIn &c) {
  return ops::to_f64(force_exact, ops::three_planes<K>(a, b, c));
}
FloatOut epeck_project_point_line_f64(bool force_exact, const Point3In &point, const Two3 &line) {
  return ops::to_f64(force_exact, ops::project_point_line<K>(point, line));
}
FloatOut epeck_project_point_plane_f64(bool force_exact, const Point3In &point,
                                       const PlaneIn &plane) {
  return ops::to_f64(force_exact, ops::project_point_plane<K>(point, plane));
}
FloatOut epeck_lines_2d_f64(bool force_exact, const Two2 &a, const Two2 &b) {
  return ops::to_f64(force_exact, ops::lines_2d<K>(a, b));
}
FloatOut epeck_segments_2d_f64(bool force_exact, const Two2 &a, const Two2 &b) {
  return ops::to_f64(force_exact, ops::segments_2d<K>(a, b));
}
FloatOut epeck_line_line_f64(bool force_exact, const Linear3 &a, const Linear3 &b) {
  ops::FloatSink s{force_exact};
  ops::line_line<K>(s, a, b);
  return s.out;
}

} // namespace geocert_oracle
