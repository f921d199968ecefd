#include "solver/sweep.h"

#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

#include "solver/input_error.h"

namespace ivv {

std::vector<double> linear_grid(double lo, double hi, int n) {
  std::vector<double> g(n);
  for (int i = 0; i < n; ++i) g[i] = n == 1 ? lo : lo + (hi - lo) * i / (n - 1);
  return g;
}

std::vector<double> log_grid(double lo, double hi, int n) {
  std::vector<double> g(n);
  const double a = std::log(lo), b = std::log(hi);
  for (int i = 0; i < n; ++i) g[i] = n == 1 ? lo : std::exp(a + (b - a) * i / (n - 1));
  if (n > 1) g.back() = hi;
  return g;
}

std::vector<SweepPoint> run_sweep(const SweepRequest& req) {
  if (req.velocities.empty()) throw InputError("--v0", "the velocity grid is empty");
  if (req.zetas.empty()) throw InputError("--zeta", "the damping grid is empty");
  for (double v : req.velocities)
    if (!(std::isfinite(v) && v > 0))
      throw InputError("--v0", "velocities must be finite and > 0 m/s");
  for (double z : req.zetas)
    if (!(std::isfinite(z) && z >= 0))
      throw InputError("--zeta", "damping ratios must be finite and >= 0 (0: no dashpot)");
  for (double z : req.zetas)
    if (z > 0 && !req.base.scene.yield_strength)
      throw InputError("--zeta",
                       "a damping ratio is defined with K_y and needs target.yield_strength; "
                       "this scene has none: use --zeta 0 (no dashpot)");

  std::vector<SweepPoint> points;
  for (double v : req.velocities)
    for (double z : req.zetas) points.push_back({v, z, {}});
  // validate the shared request once, so that workers cannot throw InputError
  {
    SimulationRequest probe = req.base;
    probe.scene.velocity = req.velocities.front();
    validate(probe);
  }

  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex progress_mutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < points.size(); i = next++) {
      SimulationRequest r = req.base;
      r.scene.velocity = points[i].v0;
      r.scene.damping = points[i].zeta > 0 ? Damping::ratio(points[i].zeta) : Damping::none();
      points[i].result = simulate(r);
      if (req.progress) {
        std::lock_guard lock(progress_mutex);
        req.progress(++done, points.size());
      }
    }
  };
  int threads =
      req.threads > 0 ? req.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(1, std::min<int>(threads, static_cast<int>(points.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  return points;
}

}  // namespace ivv
