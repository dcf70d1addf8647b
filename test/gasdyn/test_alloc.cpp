// No heap allocation inside a time step: global operator new is replaced by a counting version
// (test/common/alloc_counter.hpp, linked into this test executable only); a network with every
// element kind is advanced after a warm-up and the allocation count must not change.
#include <gtest/gtest.h>

#include <memory>

#include "../common/alloc_counter.hpp"
#include "gasdyn/network.hpp"
#include "gasdyn/turbo_boundaries.hpp"

using namespace hbt::gasdyn;

namespace {
class Map final : public FlowMap {
 public:
  double massFlow(double p0, double T0, double p, double) const override {
    return nozzleMassFlow(hbt::PerfectGas{}, 2e-4, p0, T0, p);
  }
};
}  // namespace

TEST(Allocation, NoneDuringStepping) {
  for (SolverKind s : {SolverKind::FSM, SolverKind::TVD}) {
    Network net;
    auto cfg = [&](const char* n) {
      PipeConfig c;
      c.name = n, c.length = 0.5, c.cells = 25, c.solver = s, c.friction_darcy = 0.02;
      c.heat = WallHeat::ReynoldsAnalogy, c.T_wall = 350.0;
      return c;
    };
    Pipe& a = net.addPipe(cfg("a"));
    Pipe& b = net.addPipe(cfg("b"));
    Pipe& c = net.addPipe(cfg("c"));
    Pipe& d = net.addPipe(cfg("d"));
    a.setUniform(2e5, 400.0);
    for (Pipe* p : {&b, &c, &d}) p->setUniform(1e5, 300.0);
    Volume& amb = net.addReservoir("amb", 1e5, 300.0);
    Volume& cyl = net.addVolume("cyl", 1e-3, 3e5, 800.0);
    Volume& j = net.addVolume("j", 1e-4, 1e5, 300.0);
    net.add<Valve>("valve", cyl, leftEnd(a), std::make_shared<ConstantArea>(1e-4, 0.7, 0.7));
    net.connect(a, End::Right, j);
    net.connect(b, End::Left, j);
    net.add<PipeOrifice>("orifice", rightEnd(b), leftEnd(c),
                         std::make_shared<ConstantArea>(1e-4, 0.8, 0.8));
    net.add<TurbineEntry>("turbine", rightEnd(c), amb, std::make_shared<Map>());
    net.add<CompressorOutlet>("compressor", amb, leftEnd(d), std::make_shared<Map>());
    net.close(d, End::Right);
    net.advance(1e-4);  // warm-up (validation etc.)
    const long before = hbt::testing::allocations();
    ASSERT_GT(before, 0) << "counting operator new not active";
    net.advance(5e-3);
    EXPECT_EQ(hbt::testing::allocations() - before, 0) << "solver " << (s == SolverKind::FSM ? "fsm" : "tvd");
    EXPECT_GT(net.steps(), 20);
  }
}
