#pragma once
// ReadLiggghtsDump: the last snapshot of a LIGGGHTS text dump (`dump custom` or `write_dump
// custom` with at least the columns id x y z radius; type, vx vy vz and mass when present) as
// an objectives::Snapshot, so demcal's metrics (the repose angle) measure a LIGGGHTS run as they
// measure demcal's own. Every atom is one grain (multisphere members are not grouped): use it on
// sphere runs. Grain species = atom type − 1 (demcal's material index in an exported deck).
//
//   objectives::Snapshot s;
//   if (!ReadLiggghtsDump("deck/post/final.liggghts", &s, &error)) ...;
#include <string>

#include "objectives/common/snapshot.h"

namespace demcal::workflow {

// False with *error naming the file and the line on a missing column or a malformed row.
bool ReadLiggghtsDump(const std::string& path, objectives::Snapshot* out, std::string* error);

}  // namespace demcal::workflow
