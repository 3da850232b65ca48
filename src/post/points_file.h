// SeaSpring — MIT licence.
/// \file points_file.h
/// \brief The points file of `seaspring-post measure -points FILE` (DualSPHysics MeasureTool's
///        -points file), in one of two forms:
///   POINTS            then one point per line:  x y z
///   POINTSLIST        then three lines:         BeginX BeginY BeginZ
///                                               StepX StepY StepZ
///                                               CountX CountY CountZ
///                     giving the CountX*CountY*CountZ points Begin + (i,j,k)*Step, x fastest.
/// Blank lines are ignored and '#' starts a comment (to the end of the line) anywhere; the keyword is
/// case-insensitive. Anything else (a missing keyword, a line without exactly three numbers, a
/// count that is not a positive integer, extra lines after a POINTSLIST, no point at all) is
/// an error naming the file and line.
#pragma once

#include <string>
#include <vector>

#include "core/vec3.h"

namespace seaspring::post {

/// Reads the points of a points file (above). Throws seaspring::Error "FILE:LINE: message".
std::vector<Vec3d> readPointsFile(const std::string& path);

/// The same from text already read (`path` names it in errors).
std::vector<Vec3d> parsePoints(const std::string& text, const std::string& path);

}  // namespace seaspring::post
