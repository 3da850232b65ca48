// SeaSpring — MIT licence.
/// \file shapes.h
/// \brief Rasterisation of GenCase shapes onto the lattice.
///
/// One rule for every shape: a lattice point belongs to a shape when it lies within half a
/// dp of it. For axis-aligned boxes this is exactly GenCase's rounding of each bound to the
/// nearest lattice plane (a face at x = 0.67 with dp = 0.0085 lands on the plane k = 79).
/// Shapes are given in their own coordinates and placed by the current transform
/// (`move`, `rotate`).
#pragma once

#include <cstdint>

#include "core/vec3.h"
#include "gencase/lattice_grid.h"

namespace seaspring::gencase {

/// Affine map x' = R x + t.
struct Affine {
    double r[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    Vec3d t{0, 0, 0};

    Vec3d apply(Vec3d p) const;
    Affine inverse() const;                    ///< R is a rotation: R^-1 = R^T
    Affine then(const Affine& inner) const;    ///< this * inner (inner acts first)
    bool hasRotation() const;
    static Affine translation(Vec3d d);
    static Affine rotation(double angle_deg, Vec3d axis);
};

/// Box faces (GenCase names): left x-, right x+, front y-, back y+, bottom z-, top z+.
enum BoxFaces : unsigned {
    FaceLeft = 1, FaceRight = 2, FaceFront = 4, FaceBack = 8, FaceBottom = 16, FaceTop = 32,
    FacesAll = 63, BoxSolid = 64,
};

enum class DrawMode { Full, Face, Solid };

/// Sets `value` on the lattice points of a box [p0, p0+size] (each component of size may be
/// negative) covering `faces` (a BoxFaces mask, or BoxSolid). Returns points written.
std::size_t drawBox(LatticeGrid& g, const Affine& m, Vec3d p0, Vec3d size, unsigned faces,
                    std::uint16_t value);
/// Cylinder of `radius` with axis p1→p2 (both covers closed).
std::size_t drawCylinder(LatticeGrid& g, const Affine& m, Vec3d p1, Vec3d p2, double radius,
                         DrawMode mode, std::uint16_t value);
std::size_t drawSphere(LatticeGrid& g, const Affine& m, Vec3d centre, double radius,
                       DrawMode mode, std::uint16_t value);

/// What a flood fill may pass through.
enum FillMask : unsigned { FillVoid = 1, FillFluid = 2, FillBound = 4, FillBorder = 8 };

/// Flood fill (6-connected; 4-connected in 2D) from `seed` through lattice points whose
/// content matches `mask`, strictly inside the box [p0, p0+size] (its bounds rounded to the
/// lattice like drawBox); with FillBorder the box's border planes may be filled too. This is
/// GenCase's rule: the SPHERIC benchmark's water block (fillbox to z = 0.55 m at dp 0.025)
/// holds 21 layers, not 22. Points with MK <= fluid_mk_max are
/// fluid, larger MKs boundary. Requires a transform without rotation. Returns points written.
std::size_t fillBox(LatticeGrid& g, const Affine& m, Vec3d seed, Vec3d p0, Vec3d size,
                    unsigned mask, std::uint16_t value, std::uint16_t fluid_mk_max);

}  // namespace seaspring::gencase
