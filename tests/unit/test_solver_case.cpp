// SeaSpring — MIT licence.
/// \file test_solver_case.cpp
/// \brief loadSolverCase on cases generated in-process by gencase (a pool, a case with a
///        moving boundary, a VCPM solid and gauges, a 2D case). Its errors on edited copies of
///        the resolved XML: test_solver_case_errors.cpp.
#include "solver_case_test_util.h"

using namespace seaspring;
using namespace seaspring::test::solver_case;

namespace fs = std::filesystem;

// ---- Loading generated cases ---------------------------------------------------------------

TEST(SolverCase, LoadsThePoolAsGencaseWroteIt) {
    const Generated& p = pool();
    const solver::SolverCase c = loadSolverCase(p.base);
    EXPECT_EQ(c.name, "Case");
    EXPECT_EQ(c.xml_path, p.base + ".xml");
    EXPECT_EQ(fs::canonical(c.h5_path), fs::canonical(p.base + ".h5"));
    EXPECT_EQ(c.nfixed, 25u);
    EXPECT_EQ(c.nmoving, 0u);
    EXPECT_EQ(c.nsolid, 0u);
    EXPECT_EQ(c.nfluid, 125u);
    ASSERT_EQ(c.blocks.size(), 2u);
    EXPECT_EQ(c.blocks[0].type, ParticleType::Fixed);
    EXPECT_EQ(c.blocks[0].mk, 10);
    EXPECT_EQ(c.blocks[0].mk_local, 0);
    EXPECT_EQ(c.blocks[0].begin, 0u);
    EXPECT_EQ(c.blocks[0].count, 25u);
    EXPECT_EQ(c.blocks[1].type, ParticleType::Fluid);
    EXPECT_EQ(c.blocks[1].mk, 1);
    EXPECT_EQ(c.blocks[1].mk_local, 0);
    EXPECT_EQ(c.blocks[1].begin, 25u);
    EXPECT_EQ(c.blocks[1].count, 125u);
    // Constants and domain round-trip exactly (written with 17 digits).
    EXPECT_EQ(c.constants.dimensions, 3);
    EXPECT_EQ(c.constants.dp, p.g.constants.dp);
    EXPECT_EQ(c.constants.h, p.g.constants.h);
    EXPECT_EQ(c.constants.speedsound, p.g.constants.speedsound);
    EXPECT_EQ(c.constants.b, p.g.constants.b);
    EXPECT_EQ(c.constants.massfluid, p.g.constants.massfluid);
    EXPECT_EQ(c.constants.massbound, p.g.constants.massbound);
    EXPECT_EQ(c.params.cfl_number, p.g.constants.cflnumber);
    EXPECT_EQ(c.domain_min.x, p.g.domain.min.x);
    EXPECT_EQ(c.domain_min.z, p.g.domain.min.z);
    EXPECT_EQ(c.domain_max.y, p.g.domain.max.y);
    EXPECT_EQ(c.domain_max.z, p.g.domain.max.z);
    // Particles are those gencase generated.
    ASSERT_EQ(c.particles.size(), p.g.particles.size());
    for (std::size_t i = 0; i < c.particles.size(); ++i) {
        ASSERT_EQ(c.particles.id[i], p.g.particles.id[i]) << i;
        ASSERT_EQ(c.particles.pos[i].z, p.g.particles.pos[i].z) << i;
        ASSERT_EQ(c.particles.rhop[i], p.g.particles.rhop[i]) << i;
    }
    EXPECT_FALSE(c.bonds.has_value());
    EXPECT_TRUE(c.motion.empty());
    EXPECT_EQ(c.solid_bodies, 0u);
    EXPECT_TRUE(c.notes.empty());
}

TEST(SolverCase, DefaultsAndGivenParameters) {
    const solver::SolverCase d = loadSolverCase(pool().base);
    const solver::SolverParameters def;
    EXPECT_EQ(d.params.step_algorithm, def.step_algorithm);
    EXPECT_EQ(d.params.verlet_steps, 40);
    EXPECT_EQ(d.params.kernel, 2);
    EXPECT_EQ(d.params.visco_treatment, 1);
    EXPECT_EQ(d.params.visco, 0.1);
    EXPECT_EQ(d.params.time_max, 1.0);
    EXPECT_EQ(d.params.time_out, 0.1);
    EXPECT_EQ(d.params.rhop_out_min, 700);
    EXPECT_EQ(d.params.rhop_out_max, 1300);
    EXPECT_EQ(d.params.coef_dt_min, 0.05);
    EXPECT_EQ(d.params.density_dt, 0);
    EXPECT_EQ(d.params.density_dt_value, 0.1);
    EXPECT_FALSE(d.params.dt_all_particles);

    const Generated g = generate(
        "params", kPool, "", "",
        "<parameter key=\"StepAlgorithm\" value=\"2\"/><parameter key=\"VerletSteps\" "
        "value=\"30\"/>"
        "<parameter key=\"Kernel\" value=\"1\"/><parameter key=\"ViscoTreatment\" value=\"2\"/>"
        "<parameter key=\"ViscoBoundFactor\" value=\"2\"/><parameter key=\"DensityDT\" "
        "value=\"3\"/>"
        "<parameter key=\"DensityDTvalue\" value=\"0.2\"/><parameter key=\"CoefDtMin\" "
        "value=\"0.1\"/>"
        "<parameter key=\"DtIni\" value=\"1e-4\"/><parameter key=\"DtMin\" value=\"1e-5\"/>"
        "<parameter key=\"DtFixed\" value=\"2e-4\"/><parameter key=\"RhopOutMin\" value=\"800\"/>"
        "<parameter key=\"RhopOutMax\" value=\"1200\"/><parameter key=\"MinFluidStop\" "
        "value=\"0.5\"/>"
        "<parameter key=\"WrnPartsOut\" value=\"5\"/><parameter key=\"SlipMode\" value=\"2\"/>"
        "<parameter key=\"ShiftTFS\" value=\"1.5\"/>");
    const solver::SolverParameters p = loadSolverCase(g.base).params;
    EXPECT_EQ(p.step_algorithm, 2);
    EXPECT_EQ(p.verlet_steps, 30);
    EXPECT_EQ(p.kernel, 1);
    EXPECT_EQ(p.visco_treatment, 2);
    EXPECT_EQ(p.visco_bound_factor, 2.0);
    EXPECT_EQ(p.density_dt, 3);
    EXPECT_EQ(p.density_dt_value, 0.2);
    EXPECT_EQ(p.coef_dt_min, 0.1);
    EXPECT_EQ(p.dt_ini, 1e-4);
    EXPECT_EQ(p.dt_min, 1e-5);
    EXPECT_EQ(p.dt_fixed, 2e-4);
    EXPECT_EQ(p.rhop_out_min, 800);
    EXPECT_EQ(p.rhop_out_max, 1200);
    EXPECT_EQ(p.min_fluid_stop, 0.5);
    EXPECT_EQ(p.wrn_parts_out, 5);
}

TEST(SolverCase, PathMayNameTheXmlOrTheH5) {
    const Generated& p = pool();
    EXPECT_EQ(loadSolverCase(p.base + ".xml").xml_path, p.base + ".xml");
    EXPECT_EQ(loadSolverCase(p.base + ".h5").xml_path, p.base + ".xml");
}

TEST(SolverCase, AbsentKeyTakesTheTableDefault) {
    const Edited e = edit(pool(), "<parameter key=\"Kernel\" value=\"2\" />", "");
    EXPECT_EQ(e.error, "");
    EXPECT_EQ(loadSolverCase(e.path).params.kernel, 2);
}

TEST(SolverCase, MovingBoundarySolidAndGauges) {
    const Generated g =
        generate("moving_solid", std::string(kPool) + "\n" + kMovingAndSolid, kMotion, kSolid);
    const solver::SolverCase c = loadSolverCase(g.base);
    EXPECT_EQ(c.nfixed, 33u);  // floor 25 + clamp 8
    EXPECT_EQ(c.nmoving, 25u);
    EXPECT_EQ(c.nsolid, 12u);
    EXPECT_EQ(c.nfluid, 125u);
    ASSERT_EQ(c.blocks.size(), 5u);
    EXPECT_EQ(c.blocks[2].type, ParticleType::Moving);
    EXPECT_EQ(c.blocks[2].mk_local, 1);
    EXPECT_EQ(c.blocks[2].begin, 33u);
    EXPECT_EQ(c.blocks[3].type, ParticleType::Solid);
    EXPECT_EQ(c.blocks[3].mk_local, 2);
    ASSERT_EQ(c.motion.objects.size(), 1u);
    EXPECT_EQ(c.motion.objects[0].mkbound, 1);
    ASSERT_TRUE(c.bonds.has_value());
    EXPECT_EQ(c.bonds->first_solid, 58u);
    EXPECT_EQ(c.bonds->solidCount(), 12u);
    EXPECT_EQ(c.bonds->bondSlots(), g.g.bonds.bondSlots());
    EXPECT_EQ(c.solid_bodies, 1u);
    // The same SolidBody gencase wrote (the case model's), read back.
    ASSERT_EQ(c.solids.size(), 1u);
    ASSERT_EQ(g.g.solids.size(), 1u);
    EXPECT_EQ(c.solids[0].mkbound, 2);
    EXPECT_EQ(c.solids[0].mk, g.g.solids[0].mk);
    EXPECT_EQ(c.solids[0].clamp_mkbound, std::vector<int>{3});
    EXPECT_EQ(c.solids[0].clamp_mk, g.g.solids[0].clamp_mk);
    EXPECT_EQ(c.solids[0].youngmod, 3e6);
    EXPECT_EQ(c.solids[0].declared_in, "vcpmsolids");
    EXPECT_EQ(c.solids[0].particles, 12u);
    EXPECT_EQ(g.g.solids[0].particles, 12u);
    // The gauges as gencase resolved them (expression evaluated) are read back.
    EXPECT_TRUE(c.notes.empty());
    ASSERT_EQ(c.gauges.gauges.size(), 1u);
    EXPECT_EQ(c.gauges.gauges[0].kind, model::GaugeKind::Velocity);
    EXPECT_EQ(c.gauges.gauges[0].name, "V");
    EXPECT_EQ(c.gauges.gauges[0].point.x, 0.25);
    EXPECT_EQ(c.gauges.defaults.output, std::optional<bool>(true));
    const std::vector<std::string> lines = solver::describeCase(c);
    std::string all;
    for (const std::string& l : lines) all += l + "\n";
    expectContains(all, "particles: 195 (fixed 33, moving 25, solid 12, fluid 125), 3D");
    expectContains(all, "motion: 1 object(s)");
    expectContains(all,
                   "VCPM solids: 1 body, " + std::to_string(g.g.bonds.bondSlots()) + " bond slots");
}

TEST(SolverCase, TwoDimensionalCaseHasAFlatDomain) {
    const Generated g = generate(
        "2d",
        "<setmkbound mk=\"0\"/><drawbox><boxfill>solid</boxfill><point x=\"0\" y=\"0\" z=\"-0.2\"/>"
        "<size x=\"0.4\" y=\"0\" z=\"0\"/></drawbox>\n<setmkfluid "
        "mk=\"0\"/><drawbox><boxfill>solid</boxfill>"
        "<point x=\"0\" y=\"0\" z=\"0\"/><size x=\"0.4\" y=\"0\" z=\"0.4\"/></drawbox>",
        "", "", "", true);
    const solver::SolverCase c = loadSolverCase(g.base);
    EXPECT_EQ(c.constants.dimensions, 2);
    EXPECT_EQ(c.nfixed, 5u);
    EXPECT_EQ(c.nfluid, 25u);
    EXPECT_EQ(c.domain_min.y, c.domain_max.y);
}

TEST(SolverCase, DescribeCaseLines) {
    const solver::SolverCase c = loadSolverCase(pool().base);
    const std::vector<std::string> lines = solver::describeCase(c);
    ASSERT_GE(lines.size(), 4u);
    EXPECT_EQ(lines[0], "particles: 150 (fixed 25, moving 0, solid 0, fluid 125), 3D");
    expectContains(lines[1], "dp=0.1 m, h=");
    expectContains(lines[1], "c0=");
    expectContains(lines[1], "B=");
    expectContains(lines[2], "mass: fluid 1 kg, boundary 1 kg");
    EXPECT_EQ(lines[3], "domain: (0, 0, -0.2) - (0.4, 0.4, 0.4) m");
}
