#include "hm/lattice2d/coupled/relaxation.hpp"

#include <algorithm>
#include <optional>

#include "hm/core/input_error.hpp"
#include "hm/lattice2d/coupled/anderson_acceleration.hpp"

namespace hm::lattice2d {

namespace {

// The paper's loop: the flow's pressure and the mechanics' displacement as they are.
class PlainPasses final : public PassRelaxation {
 public:
  void start_step() override {}
  void restart() override {}
  void next_guess(Eigen::VectorXd& p_guess, Eigen::VectorXd& u_guess, const Eigen::VectorXd& p,
                  const Eigen::VectorXd& u, bool) override {
    p_guess = p;
    u_guess = u;
  }
};

// Aitken's dynamic relaxation (Kuettler & Wall 2008) of the pressure: p_g += omega (p - p_g), omega
// from the last two residuals r = p - p_g. The displacement guess is the mechanics' u.
class AitkenPasses final : public PassRelaxation {
 public:
  explicit AitkenPasses(double initial) : initial_(initial) {}
  void start_step() override { fresh_ = true; }
  void restart() override { fresh_ = true; }
  void next_guess(Eigen::VectorXd& p_guess, Eigen::VectorXd& u_guess, const Eigen::VectorXd& p,
                  const Eigen::VectorXd& u, bool beams_broke) override {
    const Eigen::VectorXd r = p - p_guess;
    if (fresh_ || beams_broke) {
      // No last residual of this map: start from the initial factor.
      omega_ = initial_;
    } else {
      const Eigen::VectorXd dr = r - r_prev_;
      const double dr2 = dr.squaredNorm();
      if (dr2 > 0.0) omega_ = std::clamp(-omega_ * r_prev_.dot(dr) / dr2, -1.0, 1.0);
    }
    fresh_ = false;
    r_prev_ = r;
    p_guess += omega_ * r;
    u_guess = u;
  }

 private:
  double initial_;
  double omega_ = 1.0;
  bool fresh_ = true;
  Eigen::VectorXd r_prev_;
};

// Anderson acceleration of the pass map (p_g, u_g) -> (p, u): u_g enters through the springs, so both
// are the state; u is scaled to the pressure's magnitude, fixed for the step so that the secants stay
// consistent.
class AndersonPasses final : public PassRelaxation {
 public:
  AndersonPasses(double mixing, int depth) : mixing_(mixing), depth_(depth) {}
  void start_step() override {
    anderson_.emplace(depth_, mixing_);
    u_scale_ = 1.0;
    u_scaled_ = false;
  }
  void restart() override { anderson_->reset(); }
  void next_guess(Eigen::VectorXd& p_guess, Eigen::VectorXd& u_guess, const Eigen::VectorXd& p,
                  const Eigen::VectorXd& u, bool beams_broke) override {
    if (beams_broke) anderson_->reset();  // the map changed: old differences mislead
    const double u_max = u.cwiseAbs().maxCoeff(), p_max = p.cwiseAbs().maxCoeff();
    if (!u_scaled_ && u_max > 0.0 && p_max > 0.0) {  // first pass with a non-zero u (from rest: pass 2)
      u_scale_ = p_max / u_max;
      u_scaled_ = true;
      anderson_->reset();
    }
    const Eigen::Index np = p.size(), nu = u.size();
    Eigen::VectorXd state(np + nu), mapped(np + nu);
    state << p_guess, u_scale_ * u_guess;
    mapped << p, u_scale_ * u;
    const Eigen::VectorXd next = anderson_->next(state, mapped);
    p_guess = next.head(np);
    u_guess = next.tail(nu) / u_scale_;
  }

 private:
  double mixing_;
  int depth_;
  std::optional<AndersonAcceleration> anderson_;
  double u_scale_ = 1.0;
  bool u_scaled_ = false;
};

}  // namespace

std::unique_ptr<PassRelaxation> make_pass_relaxation(CouplingRelaxation kind, double initial_relaxation,
                                                     int anderson_depth) {
  switch (kind) {
    case CouplingRelaxation::aitken: return std::make_unique<AitkenPasses>(initial_relaxation);
    case CouplingRelaxation::anderson: return std::make_unique<AndersonPasses>(initial_relaxation, anderson_depth);
    case CouplingRelaxation::none: break;
  }
  return std::make_unique<PlainPasses>();
}

}  // namespace hm::lattice2d
