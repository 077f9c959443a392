// Kernel-generic pieces of the oracle: building CGAL objects from the bridge's
// double inputs, the eight operations, and writing any result into the bridge's
// output structs. Included by epeck.cpp and epick.cpp, which instantiate it for
// one kernel each (two translation units keep the compile time in check).
#pragma once

#include <CGAL/Intersections_2/Line_2_Line_2.h>
#include <CGAL/Intersections_2/Segment_2_Segment_2.h>
#include <CGAL/Intersections_3/Line_3_Line_3.h>
#include <CGAL/Intersections_3/Line_3_Plane_3.h>
#include <CGAL/Intersections_3/Line_3_Ray_3.h>
#include <CGAL/Intersections_3/Line_3_Segment_3.h>
#include <CGAL/Intersections_3/Plane_3_Plane_3.h>
#include <CGAL/Intersections_3/Plane_3_Plane_3_Plane_3.h>
#include <CGAL/Intersections_3/Plane_3_Segment_3.h>
#include <CGAL/Intersections_3/Ray_3_Ray_3.h>
#include <CGAL/Intersections_3/Ray_3_Segment_3.h>
#include <CGAL/Intersections_3/Segment_3_Segment_3.h>
#include <boost/multiprecision/gmp.hpp>
#include <boost/optional.hpp>
#include <boost/variant.hpp>
#include <gmp.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "geocert/oracle/oracle.h"
#include "geocert/src/oracle/ffi.rs.h"

namespace geocert_oracle {
namespace ops {

// ---- errors ---------------------------------------------------------------

/// Degenerate input: "geocert:<kind>:<field>", parsed on the Rust side into a
/// GeomError naming the argument.
[[noreturn]] inline void reject(const char *kind, const char *field) {
  throw std::invalid_argument(std::string("geocert:") + kind + ":" + field);
}

// ---- inputs ---------------------------------------------------------------

template <class K> typename K::Point_3 point3(const double *a) {
  return typename K::Point_3(a[0], a[1], a[2]);
}
template <class K> typename K::Vector_3 vector3(const double *a) {
  return typename K::Vector_3(a[0], a[1], a[2]);
}
template <class K> typename K::Point_2 point2(const double *a) {
  return typename K::Point_2(a[0], a[1]);
}
template <class K> typename K::Vector_2 vector2(const double *a) {
  return typename K::Vector_2(a[0], a[1]);
}

/// Implicit: a x + b y + c z + d = 0 from v[0..4]. Parametric: origin v[0..3],
/// u v[3..6], v v[6..9], built as Plane_3(origin, u × v). Epeck evaluates the cross
/// product and d = −n·origin exactly; Epick rounds them.
template <class K> typename K::Plane_3 plane(const PlaneIn &in, const char *field) {
  const double *v = in.v.data();
  if (in.implicit) {
    typename K::Plane_3 pl(v[0], v[1], v[2], v[3]);
    if (pl.is_degenerate()) reject("zero_normal", field);
    return pl;
  }
  typename K::Plane_3 pl(point3<K>(v), CGAL::cross_product(vector3<K>(v + 3), vector3<K>(v + 6)));
  if (pl.is_degenerate()) reject("collinear_plane_vectors", field);
  return pl;
}

/// Line through `a` with direction `b`.
template <class K> typename K::Line_3 line3(const Two3 &in, const char *field) {
  typename K::Line_3 l(point3<K>(in.a.data()), vector3<K>(in.b.data()));
  if (l.is_degenerate()) reject("zero_direction", field);
  return l;
}
template <class K> typename K::Segment_3 segment3(const Two3 &in, const char *field) {
  typename K::Segment_3 s(point3<K>(in.a.data()), point3<K>(in.b.data()));
  if (s.is_degenerate()) reject("degenerate_segment", field);
  return s;
}
template <class K> typename K::Line_2 line2(const Two2 &in, const char *field) {
  typename K::Line_2 l(point2<K>(in.a.data()), vector2<K>(in.b.data()));
  if (l.is_degenerate()) reject("zero_direction", field);
  return l;
}
template <class K> typename K::Segment_2 segment2(const Two2 &in, const char *field) {
  typename K::Segment_2 s(point2<K>(in.a.data()), point2<K>(in.b.data()));
  if (s.is_degenerate()) reject("degenerate_segment", field);
  return s;
}

/// Calls `f` with the CGAL object of a line ∩ line argument: Segment_3(a, b) for a
/// segment; for the line through `a` with direction `b` restricted to [lo, hi]:
/// Line_3 when both ends are open (infinite), Ray_3 from a + lo·b along b or from
/// a + hi·b along −b when one is, Segment_3(a + lo·b, a + hi·b) when neither. The end
/// points are constructed in the kernel's arithmetic: exactly in Epeck, rounded in
/// Epick (exact there for an end at 0, the only one the benchmarks use).
template <class K, class F> void with_linear3(const Linear3 &in, const char *field, F &&f) {
  if (in.segment) {
    f(segment3<K>(Two3{in.a, in.b}, field));
    return;
  }
  typename K::Point_3 p = point3<K>(in.a.data());
  typename K::Vector_3 d = vector3<K>(in.b.data());
  if (d == CGAL::NULL_VECTOR) reject("zero_direction", field);
  const bool has_lo = std::isfinite(in.lo), has_hi = std::isfinite(in.hi);
  auto at = [&](double t) { return t == 0.0 ? p : p + d * typename K::FT(t); };
  if (!has_lo && !has_hi) {
    f(typename K::Line_3(p, d));
  } else if (has_lo && !has_hi) {
    f(typename K::Ray_3(at(in.lo), d));
  } else if (!has_lo) {
    f(typename K::Ray_3(at(in.hi), -d));
  } else {
    if (!(in.lo < in.hi)) reject("degenerate_segment", field);
    f(typename K::Segment_3(at(in.lo), at(in.hi)));
  }
}

// ---- the operations -------------------------------------------------------
// Arguments are built one after the other so that the first degenerate one is
// the one reported.

template <class K> auto line_plane(const Two3 &line, const PlaneIn &plane_in) {
  auto l = line3<K>(line, "line");
  auto p = plane<K>(plane_in, "plane");
  return CGAL::intersection(l, p);
}
template <class K> auto segment_plane(const Two3 &segment, const PlaneIn &plane_in) {
  auto s = segment3<K>(segment, "segment");
  auto p = plane<K>(plane_in, "plane");
  return CGAL::intersection(s, p);
}
template <class K> auto plane_plane(const PlaneIn &a, const PlaneIn &b) {
  auto pa = plane<K>(a, "a");
  auto pb = plane<K>(b, "b");
  return CGAL::intersection(pa, pb);
}
template <class K> auto three_planes(const PlaneIn &a, const PlaneIn &b, const PlaneIn &c) {
  auto pa = plane<K>(a, "a");
  auto pb = plane<K>(b, "b");
  auto pc = plane<K>(c, "c");
  return CGAL::intersection(pa, pb, pc);
}
template <class K> auto project_point_line(const Point3In &point, const Two3 &line) {
  auto l = line3<K>(line, "line");
  return l.projection(point3<K>(point.data()));
}
template <class K> auto project_point_plane(const Point3In &point, const PlaneIn &plane_in) {
  auto p = plane<K>(plane_in, "plane");
  return p.projection(point3<K>(point.data()));
}
template <class K> auto lines_2d(const Two2 &a, const Two2 &b) {
  auto la = line2<K>(a, "a");
  auto lb = line2<K>(b, "b");
  return CGAL::intersection(la, lb);
}
template <class K> auto segments_2d(const Two2 &a, const Two2 &b) {
  auto sa = segment2<K>(a, "a");
  auto sb = segment2<K>(b, "b");
  return CGAL::intersection(sa, sb);
}

// ---- outputs --------------------------------------------------------------

/// The canonical decimal "p/q" (or "p" when q = 1) of a GMP rational: GMP keeps
/// every mpq in lowest terms with a positive denominator.
inline rust::String mpq_string(mpq_srcptr q) {
  std::string buf(mpz_sizeinbase(mpq_numref(q), 10) + mpz_sizeinbase(mpq_denref(q), 10) + 3, '\0');
  mpq_get_str(&buf[0], 10, q);
  return rust::String(buf.c_str(), std::strlen(buf.c_str()));
}

/// CGAL 5.5 with GMP and Boost.Multiprecision available (Debian's build) makes
/// Epeck's exact type boost::multiprecision::mpq_rational (gmp_rational backend).
/// Any other exact type has no overload here and fails to compile rather than print
/// something non-canonical.
template <boost::multiprecision::expression_template_option ET>
rust::String rational_string(
    const boost::multiprecision::number<boost::multiprecision::gmp_rational, ET> &q) {
  return mpq_string(q.backend().data());
}
#ifdef CGAL_GMPQ_H
inline rust::String rational_string(const CGAL::Gmpq &q) { return mpq_string(q.mpq()); }
#endif

/// Writes exact rationals (Epeck only).
struct ExactSink {
  ExactOut out{};
  void kind(Kind k) { out.kind = k; }
  template <class FT> void put(const FT &x) { out.v.push_back(rational_string(CGAL::exact(x))); }
};

/// Writes doubles: Epick's own; for Epeck either to_double of the lazy interval
/// approximation (`force_exact` false: its midpoint, not the nearest double) or
/// to_double(exact(x)) (`force_exact` true: Boost converts the GMP rational
/// correctly rounded to nearest).
struct FloatSink {
  bool force_exact;
  FloatOut out{};
  std::size_t n = 0;
  void kind(Kind k) { out.kind = k; }
  template <class FT> void put(const FT &x) {
    if constexpr (std::is_same_v<FT, double>) {
      out.v[n++] = x;
    } else {
      out.v[n++] = force_exact ? CGAL::to_double(CGAL::exact(x)) : CGAL::to_double(x);
    }
  }
};

template <class S, class K> void emit(S &s, const CGAL::Point_3<K> &p) {
  s.kind(Kind::Point);
  s.put(p.x()), s.put(p.y()), s.put(p.z());
}
template <class S, class K> void emit_vector(S &s, const CGAL::Vector_3<K> &v) {
  s.put(v.x()), s.put(v.y()), s.put(v.z());
}
/// A line as CGAL stores it: its point() and to_vector().
template <class S, class K> void emit(S &s, const CGAL::Line_3<K> &l) {
  emit(s, l.point());
  emit_vector(s, l.to_vector());
  s.kind(Kind::Line);
}
template <class S, class K> void emit(S &s, const CGAL::Segment_3<K> &seg) {
  emit(s, seg.source());
  emit(s, seg.target());
  s.kind(Kind::Segment);
}
/// A ray as its source() and to_vector().
template <class S, class K> void emit(S &s, const CGAL::Ray_3<K> &r) {
  emit(s, r.source());
  emit_vector(s, r.to_vector());
  s.kind(Kind::Ray);
}
/// A plane as its coefficients a, b, c, d of a x + b y + c z + d = 0.
template <class S, class K> void emit(S &s, const CGAL::Plane_3<K> &p) {
  s.kind(Kind::Plane);
  s.put(p.a()), s.put(p.b()), s.put(p.c()), s.put(p.d());
}
template <class S, class K> void emit(S &s, const CGAL::Point_2<K> &p) {
  s.kind(Kind::Point);
  s.put(p.x()), s.put(p.y());
}
/// A 2D line as point(0) and to_vector() (CGAL stores a, b, c).
template <class S, class K> void emit(S &s, const CGAL::Line_2<K> &l) {
  emit(s, l.point(0));
  auto v = l.to_vector();
  s.put(v.x()), s.put(v.y());
  s.kind(Kind::Line);
}
template <class S, class K> void emit(S &s, const CGAL::Segment_2<K> &seg) {
  emit(s, seg.source());
  emit(s, seg.target());
  s.kind(Kind::Segment);
}
/// CGAL 5.5 intersection results: boost::optional<boost::variant<...>>; none is
/// the empty set.
template <class S, class... T>
void emit(S &s, const boost::optional<boost::variant<T...>> &r) {
  if (!r) {
    s.kind(Kind::Empty);
    return;
  }
  boost::apply_visitor([&s](const auto &object) { emit(s, object); }, *r);
}

/// Line ∩ line for lines, rays, ranged lines and segments (every pair CGAL 5.5
/// intersects), written to `sink` (after the emit overloads, which it finds by
/// ordinary lookup).
template <class K, class S> void line_line(S &sink, const Linear3 &a, const Linear3 &b) {
  with_linear3<K>(a, "a", [&](const auto &x) {
    with_linear3<K>(b, "b", [&](const auto &y) { emit(sink, CGAL::intersection(x, y)); });
  });
}

template <class R> ExactOut exact(const R &result) {
  ExactSink s;
  emit(s, result);
  return std::move(s.out);
}
template <class R> FloatOut to_f64(bool force_exact, const R &result) {
  FloatSink s{force_exact};
  emit(s, result);
  return s.out;
}

} // namespace ops
} // namespace geocert_oracle
