// SeaSpring — MIT licence.
/// \file measure.h
/// \brief `seaspring-post measure`: the kernel-sum gauges of the run (physics/gauges.h), at any
///        points, from the saved part files (DualSPHysics' MeasureTool).
///
/// For each part file OUTDIR/data/part_NNNN.h5 the fluid state is rebuilt as the solver holds
/// it: the active fluid particles (type fluid, not excluded) sorted by (cell, id) (sortKey) on a
/// cell grid of cells 2h/cell_div over their bounding box grown by 4h (no skin), their PosCell
/// (makePosCell) and the cell-start array; every point is then evaluated with
/// physics::gaugeSampleAt, the function of the in-run gauges, with the kernel of the part's
/// `kernel` attribute, and Shepard-corrected with physics::shepard and kclimit.
/// Constants from the part file: h, dp, dimension, rhop0 (attributes), the fluid mass (/mass),
/// and the Tait B, recovered exactly from /press and /rhop (press = taitPressure7(rhop, B, 1/rhop0)
/// for every fluid particle; an error when no float B reproduces them).
/// 2D: points are moved onto the particles' plane (y of the fluid), as the in-run gauges.
/// Points outside the grid (farther than 4h from every fluid particle) measure nothing (0).
#pragma once

#include <string>
#include <vector>

#include "core/vec3.h"
#include "io/part_output.h"
#include "physics/gauges.h"
#include "post/part_series.h"

namespace seaspring::post {

/// What a measure row holds per point.
enum class MeasureVar { Press, Vel, Rhop, Wsum, Height };

/// "press,vel,rhop,wsum,height" (any order, case-insensitive; "all" = the first four) -> list,
/// each once, in the order given. Throws seaspring::Error on an unknown name.
std::vector<MeasureVar> parseMeasureVars(const std::string& list);

/// The kernel sums at one point: GaugeSample plus sum V W rho (for rhop).
struct PointSums {
    physics::GaugeSample g;
    double rhop = 0;  ///< sum V_j W_j rho_j
};

/// The cell grid of the measure: cells of 2h/cell_div (1..4) or of dp (5, physics::kCellDivSpacing)
/// from the fluid's bounding box grown
/// by 4h, or from `min` when given (it must lie below every fluid particle). Only the float
/// rounding of the pair offsets depends on it: with the solver's grid (its <simulationdomain>
/// minimum and cell size, and -skin:0) the sums are those of the in-run gauges bit for bit.
struct MeasureGrid {
    int cell_div = 1;
    bool has_min = false;
    Vec3d min{0, 0, 0};
};

/// The kernel sums of every point in the fluid state of one part file (see above).
/// Throws seaspring::Error (naming `what`) when the file lacks what is needed (version 1 part
/// file without /mass, unknown kernel, inconsistent press) or the grid does not fit.
std::vector<PointSums> measurePart(const io::PartData& d, const std::vector<Vec3d>& points,
                                   const MeasureGrid& grid = {}, const std::string& what = "part file");

struct MeasureOptions {
    std::string dirin;    ///< the run's OUTDIR (holds data/part_NNNN.h5)
    std::string points;   ///< points file (points_file.h)
    int first = -1, last = -1;
    std::vector<MeasureVar> vars{MeasureVar::Press};
    double kclimit = 0.5;  ///< Shepard: wsum below this gives 0 (the gauges' default)
    /// height: the mass limit as a fraction of the fluid particle's mass (0: the SWL gauge's
    /// default, physics::swlMassLimitCoef).
    double height_coef = 0;
    MeasureGrid grid;
    std::string savecsv;  ///< output CSV
};

/// Runs the measure subcommand: reads the points and the parts, writes `savecsv`
/// (';'-separated, one header line: part;time then, per variable in order, one column per point:
/// press_K [Pa]; velx_K;vely_K;velz_K [m/s]; rhop_K [kg/m^3]; wsum_K; height_K [m]: the free
/// surface above point K, found as the in-run SWL gauge finds it (physics::swlLine from the point
/// up to 2h above the highest fluid particle, spaced dp/2; physics::swlSurface on the mass sums
/// with the mass limit; the point itself when it is dry)), written under a
/// temporary name and renamed when complete. Progress lines go to `log`. Returns the rows written.
int runMeasure(const MeasureOptions& o, std::ostream& log);

}  // namespace seaspring::post
