// Small second-order models with known answers, shared by the dynamics tests.
#pragma once

#include <random>
#include <string>

#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {
namespace test {

/// m x'' + c x' + k x = k u + c_u u': a mass on a spring (and a damper) to the moving ground.
inline SecondOrderSystem oneDof(double m, double c, double k, double c_u) {
  SecondOrderSystem s;
  s.mass = Matrix::Constant(1, 1, m);
  s.damping = Matrix::Constant(1, 1, c);
  s.stiffness = Matrix::Constant(1, 1, k);
  s.input_stiffness = Matrix::Constant(1, 1, k);
  s.input_damping = Matrix::Constant(1, 1, c_u);
  s.output = Matrix::Identity(1, 1);
  s.output_names = {"mass uz"};
  s.input_stations = Vector::Zero(1);
  return s;
}

/// Quarter car q = [z_s, z_u]: sprung mass on a suspension (k_s, c_s) over an unsprung mass on a
/// stiff tyre (k_t, c_t) to the road.
inline SecondOrderSystem quarterCar(double m_s = 300.0, double m_u = 30.0, double k_s = 3e4,
                                    double c_s = 2e3, double k_t = 2e10, double c_t = 0.0) {
  SecondOrderSystem s;
  s.mass = Eigen::Vector2d(m_s, m_u).asDiagonal();
  s.stiffness.resize(2, 2);
  s.stiffness << k_s, -k_s, -k_s, k_s + k_t;
  s.damping.resize(2, 2);
  s.damping << c_s, -c_s, -c_s, c_s + c_t;
  s.input_stiffness = (Matrix(2, 1) << 0.0, k_t).finished();
  s.input_damping = (Matrix(2, 1) << 0.0, c_t).finished();
  s.output = Matrix::Identity(2, 2);
  s.output_names = {"hull uz", "wheel uz"};
  s.input_stations = Vector::Zero(1);
  return s;
}

/// Chain of n masses m joined by springs k (and dampers c); mass 0 sits on a ground spring k_0
/// (damper c_0) driven by the single road input. Outputs: every mass.
inline SecondOrderSystem chain(int n, double m, double k, double c, double k_0, double c_0) {
  SecondOrderSystem s;
  s.mass = m * Matrix::Identity(n, n);
  s.stiffness = Matrix::Zero(n, n);
  s.damping = Matrix::Zero(n, n);
  s.stiffness(0, 0) = k_0;
  s.damping(0, 0) = c_0;
  for (int i = 0; i + 1 < n; ++i) {
    s.stiffness.block(i, i, 2, 2) += k * Eigen::Matrix2d{{1, -1}, {-1, 1}};
    s.damping.block(i, i, 2, 2) += c * Eigen::Matrix2d{{1, -1}, {-1, 1}};
  }
  s.input_stiffness = Matrix::Zero(n, 1);
  s.input_stiffness(0, 0) = k_0;
  s.input_damping = Matrix::Zero(n, 1);
  s.input_damping(0, 0) = c_0;
  s.output = Matrix::Identity(n, n);
  for (int i = 0; i < n; ++i)
    s.output_names.push_back("mass_" + std::to_string(i) + " uz");
  s.input_stations = Vector::Zero(1);
  return s;
}

/// A vehicle-like random model: n DOFs coupled by random springs, `inputs` of them on stiff tyre
/// springs k_t at distinct stations, Rayleigh damping C = alpha M + beta K (and C_u = beta K_u,
/// so that the damping stays proportional), outputs the first `outputs` DOFs.
inline SecondOrderSystem randomVehicle(int n, int inputs, int outputs, unsigned seed,
                                       double k_t = 2e10, double alpha = 0.5, double beta = 1e-6) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  SecondOrderSystem s;
  // M: diagonal masses 30..3000 kg plus a weak symmetric coupling (still positive definite).
  s.mass = Matrix::Zero(n, n);
  for (int i = 0; i < n; ++i)
    s.mass(i, i) = 30.0 * std::pow(100.0, unit(rng));
  for (int i = 0; i + 1 < n; ++i) {
    const double coupling = 0.1 * unit(rng) * std::sqrt(s.mass(i, i) * s.mass(i + 1, i + 1));
    s.mass(i, i + 1) = s.mass(i + 1, i) = coupling;
  }
  // K: springs 1e4..1e7 N/m between random pairs plus a chain (connected), tyres at the inputs.
  s.stiffness = Matrix::Zero(n, n);
  auto spring = [&](int a, int b, double k) {
    s.stiffness(a, a) += k;
    s.stiffness(b, b) += k;
    s.stiffness(a, b) -= k;
    s.stiffness(b, a) -= k;
  };
  for (int i = 0; i + 1 < n; ++i)
    spring(i, i + 1, 1e4 * std::pow(1e3, unit(rng)));
  std::uniform_int_distribution<int> dof(0, n - 1);
  for (int e = 0; e < 2 * n; ++e) {
    const int a = dof(rng), b = dof(rng);
    if (a != b)
      spring(a, b, 1e4 * std::pow(1e3, unit(rng)));
  }
  s.input_stiffness = Matrix::Zero(n, inputs);
  s.input_stations.resize(inputs);
  for (int q = 0; q < inputs; ++q) {
    const int i = n - 1 - (q * n) / inputs;  // spread over the DOFs
    s.stiffness(i, i) += k_t;
    s.input_stiffness(i, q) += k_t;
    s.input_stations(q) = 2.0 - 0.35 * q;
  }
  s.damping = alpha * s.mass + beta * s.stiffness;
  s.input_damping = beta * s.input_stiffness;
  s.output = Matrix::Identity(n, n).topRows(outputs);
  for (int i = 0; i < outputs; ++i)
    s.output_names.push_back("dof_" + std::to_string(i) + " uz");
  return s;
}

}  // namespace test
}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
