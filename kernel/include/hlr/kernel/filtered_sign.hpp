// filtered_sign: the sign of an expression written once for any number type, decided on
// intervals, and exactly only when the intervals cannot decide. For predicates written by hand on
// input doubles, outside Geometry<K> (such as whether two triangles that share a corner cross
// there): the filter lives here, the expression in the algorithm.
#pragma once

#include <hlr/kernel/kernel.hpp>

#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

#include <type_traits>

namespace hlr {

// `expression(std::type_identity<NT>{})` evaluates the expression in NT and returns its sign
// (CGAL::Uncertain<CGAL::Sign> for intervals). Exact: the number type of the fallback; CGAL::Mpzf
// (no gcd, no heap for small numbers) where the expression is sums and products of doubles.
template <class Exact = CGAL::Exact_rational, class Expression>
CGAL::Sign filtered_sign(const Expression& expression) {
  {
    CGAL::Protect_FPU_rounding<true> protect;
    const CGAL::Uncertain<CGAL::Sign> s = expression(std::type_identity<CGAL::Interval_nt<false>>{});
    if (CGAL::is_certain(s)) {
      PredicateStats::add(PredicateFamily::sign, DecidedBy::interval);
      return CGAL::get_certain(s);
    }
  }
  PredicateStats::add(PredicateFamily::sign, DecidedBy::exact);
  return CGAL::make_certain(expression(std::type_identity<Exact>{}));
}

}  // namespace hlr
