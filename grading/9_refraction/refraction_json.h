#pragma once

#include "app/protocol/probe_json.h"
#include "stages/9_refraction/refraction.h"

namespace raystep::probe {

// Stage 9's values as JSON, read strictly as probe_json.h reads the rest: a medium
// {"solid", "index"}, a stack of them as a list (the first entered first), and a medium hit
// {"point", "local", "reflectance", "transmission", "solid", "entering"}.

Json medium(const Medium& m);
Medium medium_from(const Json& j);

Json media(const MediumStack& stack);
MediumStack media_from(const Json& j);

Json medium_hit(const MediumHit& hit);
MediumHit medium_hit_from(const Json& j);

}  // namespace raystep::probe
