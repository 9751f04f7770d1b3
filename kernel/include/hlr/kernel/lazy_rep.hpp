// Reading back the reps hlr makes for Epeck's lazy objects (points and numbers that keep how they
// were made), and whether an interval approximation is a point of doubles.
#pragma once

#include <CGAL/Handle.h>

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

}  // namespace hlr
