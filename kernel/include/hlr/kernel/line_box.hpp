// line_misses_box: a filter for line classification's candidates, in the kernel layer because it
// reasons about the error of approximate coordinates.
#pragma once

#include <hlr/kernel/kernel.hpp>

#include <CGAL/Bbox_2.h>
#include <CGAL/Interval_nt.h>

#include <type_traits>

namespace hlr {

// Whether the line through a and b certainly misses the closed box (its four corners strictly on
// one side), decided in interval arithmetic on enclosures of the points: a filter, whose "true" is
// the exact answer and whose "false" means "perhaps". Never true on the plain double kernel, whose
// own orientations are inexact: its drawings stay what its own predicates make them.
template <class K>
bool line_misses_box(const typename Geometry<K>::Point& a, const typename Geometry<K>::Point& b, const CGAL::Bbox_2& box) {
  if constexpr (std::is_same_v<K, DoubleKernel>) {
    return false;
  } else {
    using I = CGAL::Interval_nt<false>;
    CGAL::Protect_FPU_rounding<true> protect;
    const CGAL::Bbox_2 ea = Geometry<K>::bbox(a), eb = Geometry<K>::bbox(b);
    const I ax(ea.xmin(), ea.xmax()), ay(ea.ymin(), ea.ymax());
    const I dx = I(eb.xmin(), eb.xmax()) - ax, dy = I(eb.ymin(), eb.ymax()) - ay;
    int positive = 0;
    for (const double x : {box.xmin(), box.xmax()})
      for (const double y : {box.ymin(), box.ymax()}) {
        const I side = dx * (I(y) - ay) - dy * (I(x) - ax);
        if (side.inf() > 0) ++positive;
        else if (!(side.sup() < 0)) return false;
      }
    return positive == 0 || positive == 4;
  }
}

}  // namespace hlr
