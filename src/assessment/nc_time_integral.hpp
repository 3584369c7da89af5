// The time integral of the 3D-Nc collision rate over adaptive panels (private to pc_3d_nc.cpp
// and nc_time_integral.cpp; the method is step 5 of pc_3d_nc.cpp's header).
#pragma once

#include <vector>

#include "evade/assessment/pc_3d_nc.hpp"
#include "nc_rate.hpp"

namespace evade::assessment::nc {

struct NcPanel {
  double a = 0.0, b = 0.0;
  double nc = 0.0;        // Kronrod estimate of the integral of the rate
  double nc_small = 0.0;  // same for the small-HBR rate
  double err = 0.0;       // QUADPACK error estimate
};

// The rate's time integral over panels, refined where the error is largest.
class TimeIntegral {
 public:
  TimeIntegral(const nc::ElementPdf& p1, const nc::ElementPdf& p2, const nc::RateSettings& rs,
               const Nc3dOptions& opt)
      : p1_(p1), p2_(p2), rs_(rs), opt_(opt) {}

  double rate_at(double t_s, double* small_per_s);
  void add_panels(double a, double b, int count);
  void refine();
  double total(double NcPanel::*field) const;
  bool budget_left() const { return evaluations_ < opt_.max_rate_evaluations; }

  int evaluations_ = 0;
  double peak_ = 0.0, t_peak_ = 0.0;
  double worst_pop_failure_ = 0.0;     // largest rate at a time whose POP did not converge
  double worst_sphere_error_ = 0.0;    // largest error estimate of an unconverged sphere integral
  std::vector<NcPanel> panels_;

 private:
  NcPanel evaluate(double a, double b);

  const nc::ElementPdf& p1_;
  const nc::ElementPdf& p2_;
  nc::RateSettings rs_;
  Nc3dOptions opt_;
};

}  // namespace evade::assessment::nc
