// Reading back the reps hlr makes for Epeck's lazy objects (points and numbers that keep how they
// were made), whether an interval approximation is a point of doubles, and the lazy numbers whose
// exact value is a quotient of sums of products of doubles.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Handle.h>
#include <CGAL/Mpzf.h>

#include <array>
#include <optional>

namespace hlr {

// The lazy object's rep as a `Rep` when it is one (made by hlr), else null. CGAL's Lazy keeps its
// rep pointer private; Handle hands it out untyped (for Compact_container).
template <class Rep, class Lazy>
const Rep* rep_as(const Lazy& object) {
  const auto* rep = static_cast<const CGAL::Rep*>(static_cast<const CGAL::Handle&>(object).for_compact_container());
  return dynamic_cast<const Rep*>(rep);
}

// Whether an interval point is one point of doubles: its approximation is then its exact value.
template <class IntervalPoint>
bool is_double_point(const IntervalPoint& p) {
  return p.x().inf() == p.x().sup() && p.y().inf() == p.y().sup();
}

// A lazy number that keeps what it is made of (a parameter along a line, exact_parameter.hpp; a
// view coordinate of an input point, view.hpp), so that its exact value can be had as num / den
// in CGAL::Mpzf, without rationals, when what it is made of are doubles.
class QuotientRep : public CGAL::Lazy_exact_nt_rep<CGAL::Epeck::FT::Exact_type> {
 public:
  using CGAL::Lazy_exact_nt_rep<CGAL::Epeck::FT::Exact_type>::Lazy_exact_nt_rep;
  // (num, den), den != 0, when every number it is made of is a double; else nothing.
  virtual std::optional<std::array<CGAL::Mpzf, 2>> quotient() const = 0;
};

// v = num / den in Mpzf, when v is a QuotientRep whose parts are doubles; else nothing.
inline std::optional<std::array<CGAL::Mpzf, 2>> quotient_of(const CGAL::Epeck::FT& v) {
  const QuotientRep* rep = rep_as<QuotientRep>(v);
  return rep ? rep->quotient() : std::nullopt;
}

}  // namespace hlr
