#pragma once

// The coarse tyre as the radiation tests use it: its inflated quadratic
// section (the harmonic route), 3 x 3 contact points on tributary
// rectangles, and its radiating surface in 4 cm cells with 10 mm of
// deflection on the road.

#include "coarse_tyre.h"
#include <greentread/fe/harmonic_section.h>
#include <greentread/radiation/tyre_surface.h>

namespace test
{
  /// 3 x 3 points on 6 mm x 10 mm rectangles.
  inline greentread::periodic::PatchRequest
  radiating_patch_request()
  {
    greentread::periodic::PatchRequest r;
    r.load          = greentread::periodic::PointLoad::tributary_area;
    r.points_along  = 3;
    r.points_across = 3;
    r.length        = 0.018;
    r.width         = 0.03;
    return r;
  }

  struct RadiatingTyre
  {
    CoarseTyre                         tyre;
    greentread::fe::HarmonicSection    section;
    greentread::radiation::TyreSurface surface;

    RadiatingTyre()
        : tyre(64, radiating_patch_request(), true)
        , section(tyre.cell->section(), tyre.materials.materials(), 2)
        , surface(greentread::radiation::outer_contour(tyre.cell->section()), 0.04, 0.01)
    {
      section.inflate(2e5);
    }
  };
} // namespace test
