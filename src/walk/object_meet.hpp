// Whether an object meets a door (walk/objects.hpp): its solid, placed by a
// rigid matrix, intersects the door's closed rectangle, touching within
// kMeetTolerance · (1 + |centre|) included.
#pragma once

#include "math/portal.hpp"
#include "walk/objects.hpp"

namespace impossible::walk {

bool solid_meets_door(const ObjectSolid& solid, const math::dmat4& to_cell, const math::PortalRect& door);

// Whether some corner of the solid lies behind the door's plane by more than
// the tolerance (d < -kMeetTolerance · (1 + |centre|)).
bool solid_reaches_behind(const ObjectSolid& solid, const math::dmat4& to_cell, const math::PortalRect& door);

}  // namespace impossible::walk
