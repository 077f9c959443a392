// The oracle's Epick half: CGAL's exact-predicates, inexact-constructions kernel,
// the fast double kernel a CGAL user would otherwise pick. Its predicates are
// exact on the doubles it is given, but constructions (cross products, plane
// coefficients, the plane-plane line) round, so later predicates see rounded input.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "geocert/oracle/ops.h"

namespace geocert_oracle {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

FloatOut epick_line_plane(const Two3 &line, const PlaneIn &plane) {
  return ops::to_f64(false, ops::line_plane<K>(line, plane));
}
FloatOut epick_segment_plane(const Two3 &segment, const PlaneIn &plane) {
  return ops::to_f64(false, ops::segment_plane<K>(segment, plane));
}
FloatOut epick_plane_plane(const PlaneIn &a, const PlaneIn &b) {
  return ops::to_f64(false, ops::plane_plane<K>(a, b));
}
FloatOut epick_three_planes(const PlaneIn &a, const PlaneIn &b, const PlaneIn &c) {
  return ops::to_f64(false, ops::three_planes<K>(a, b, c));
}
FloatOut epick_project_point_line(const Point3In &point, const Two3 &line) {
  return ops::to_f64(false, ops::project_point_line<K>(point, line));
}
FloatOut epick_project_point_plane(const Point3In &point, const PlaneIn &plane) {
  return ops::to_f64(false, ops::project_point_plane<K>(point, plane));
}
FloatOut epick_lines_2d(const Two2 &a, const Two2 &b) {
  return ops::to_f64(false, ops::lines_2d<K>(a, b));
}
FloatOut epick_segments_2d(const Two2 &a, const Two2 &b) {
  return ops::to_f64(false, ops::segments_2d<K>(a, b));
}
FloatOut epick_line_line(const Linear3 &a, const Linear3 &b) {
  ops::FloatSink s{false};
  ops::line_line<K>(s, a, b);
  return s.out;
}

} // namespace geocert_oracle
