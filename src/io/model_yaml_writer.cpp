// Writing of model files (schema: doc/model_file.md): one flow-style line per item (a body
// pre-load as a block), numbers in shortest round-trip form so that load(save(m)) == m bit for
// bit.
#include <yaml-cpp/yaml.h>

#include <charconv>
#include <cmath>
#include <string>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/atomic_file.h"
#include "tracked_vehicle_dynamics/io/model_yaml.h"

namespace tracked_vehicle_dynamics {
namespace io {
namespace {

/// Shortest text that parses back to exactly `value`. A mantissa without a '.' gets ".0" so
/// that YAML 1.1 readers (PyYAML) also see a float: "1e-05" -> "1.0e-05".
std::string formatNumber(double value) {
  if (std::isnan(value))
    return ".nan";
  if (std::isinf(value))
    return value > 0 ? ".inf" : "-.inf";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  std::string text(buffer, result.ptr);
  const std::size_t exponent = text.find('e');
  if (exponent != std::string::npos && text.find('.') == std::string::npos) {
    text.insert(exponent, ".0");
  }
  return text;
}

YAML::Emitter& number(YAML::Emitter& out, double value) {
  return out << formatNumber(value);
}

/// Names that YAML would read as null are quoted; everything else yaml-cpp quotes as needed.
void name(YAML::Emitter& out, const std::string& text) {
  if (text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL") {
    out << YAML::DoubleQuoted;
  }
  out << text;
}

void vector(YAML::Emitter& out, const Eigen::Ref<const Eigen::VectorXd>& values) {
  out << YAML::Flow << YAML::BeginSeq;
  for (Eigen::Index i = 0; i < values.size(); ++i)
    number(out, values[i]);
  out << YAML::EndSeq;
}

void rows(YAML::Emitter& out, const Matrix3& matrix) {
  out << YAML::Flow << YAML::BeginSeq;
  for (int r = 0; r < 3; ++r)
    vector(out, matrix.row(r).transpose());
  out << YAML::EndSeq;
}

std::string dofDigits(const std::array<bool, kDofsPerNode>& dofs) {
  std::string digits;
  for (int d = 0; d < kDofsPerNode; ++d) {
    if (dofs[static_cast<std::size_t>(d)])
      digits.push_back(static_cast<char>('1' + d));
  }
  return digits;
}

void writeInertia(YAML::Emitter& out, const Matrix3& inertia) {
  const Matrix3 diagonal = inertia.diagonal().asDiagonal();
  if (inertia == diagonal) {
    vector(out, inertia.diagonal());
  } else if (inertia == inertia.transpose()) {
    Vector6 six;
    six << inertia(0, 0), inertia(1, 1), inertia(2, 2), inertia(0, 1), inertia(1, 2), inertia(0, 2);
    vector(out, six);
  } else {
    rows(out, inertia);  // not a valid tensor, but written as is for inspection
  }
}

void writeItems(YAML::Emitter& out, const fem::Model& model) {
  out << YAML::Key << "nodes" << YAML::Value;
  if (model.nodes.empty())
    out << YAML::Flow;  // "nodes: []" rather than a dangling "[]" line
  out << YAML::BeginSeq;
  for (const fem::Node& node : model.nodes) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "id" << YAML::Value << node.id;
    out << YAML::Key << "x" << YAML::Value;
    vector(out, node.position);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;

  if (!model.materials.empty()) {
    out << YAML::Key << "materials" << YAML::Value << YAML::BeginSeq;
    for (const fem::Material& material : model.materials) {
      out << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value;
      name(out, material.name);
      out << YAML::Key << "E" << YAML::Value;
      number(out, material.young_modulus) << YAML::Key << "G" << YAML::Value;
      number(out, material.shear_modulus) << YAML::Key << "rho" << YAML::Value;
      number(out, material.density) << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }

  if (!model.sections.empty()) {
    out << YAML::Key << "sections" << YAML::Value << YAML::BeginSeq;
    for (const fem::Section& section : model.sections) {
      out << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value;
      name(out, section.name);
      out << YAML::Key << "A" << YAML::Value;
      number(out, section.area) << YAML::Key << "Iy" << YAML::Value;
      number(out, section.iy) << YAML::Key << "Iz" << YAML::Value;
      number(out, section.iz) << YAML::Key << "J" << YAML::Value;
      number(out, section.torsion);
      if (section.shear_factor_y != 0.0) {
        out << YAML::Key << "shear_factor_y" << YAML::Value;
        number(out, section.shear_factor_y);
      }
      if (section.shear_factor_z != 0.0) {
        out << YAML::Key << "shear_factor_z" << YAML::Value;
        number(out, section.shear_factor_z);
      }
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }

  if (!model.beams.empty()) {
    out << YAML::Key << "beams" << YAML::Value << YAML::BeginSeq;
    for (const fem::Beam& beam : model.beams) {
      out << YAML::Flow << YAML::BeginMap << YAML::Key << "nodes" << YAML::Value << YAML::Flow
          << YAML::BeginSeq << beam.n1 << beam.n2 << YAML::EndSeq;
      out << YAML::Key << "material" << YAML::Value;
      name(out, beam.material);
      out << YAML::Key << "section" << YAML::Value;
      name(out, beam.section);
      out << YAML::Key << "orientation" << YAML::Value;
      vector(out, beam.orientation);
      if (beam.axial_force != 0.0) {
        out << YAML::Key << "axial_force" << YAML::Value;
        number(out, beam.axial_force);
      }
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }

  if (!model.springs.empty()) {
    out << YAML::Key << "springs" << YAML::Value << YAML::BeginSeq;
    for (const fem::Spring& spring : model.springs) {
      out << YAML::Flow << YAML::BeginMap;
      if (!spring.name.empty()) {
        out << YAML::Key << "name" << YAML::Value;
        name(out, spring.name);
      }
      out << YAML::Key << "nodes" << YAML::Value << YAML::Flow << YAML::BeginSeq << spring.n1;
      if (spring.n2 == fem::kGround) {
        out << "ground";
      } else {
        out << spring.n2;
      }
      out << YAML::EndSeq << YAML::Key << "k" << YAML::Value;
      vector(out, spring.stiffness);
      if (!spring.damping.isZero(0.0)) {
        out << YAML::Key << "c" << YAML::Value;
        vector(out, spring.damping);
      }
      if (spring.frame != Matrix3::Identity()) {
        out << YAML::Key << "frame" << YAML::Value;
        rows(out, spring.frame.transpose());  // the local axes, one per row
      }
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }

  if (!model.masses.empty()) {
    out << YAML::Key << "masses" << YAML::Value << YAML::BeginSeq;
    for (const fem::Mass& mass : model.masses) {
      out << YAML::Flow << YAML::BeginMap;
      if (!mass.name.empty()) {
        out << YAML::Key << "name" << YAML::Value;
        name(out, mass.name);
      }
      out << YAML::Key << "node" << YAML::Value << mass.node << YAML::Key << "mass" << YAML::Value;
      number(out, mass.mass);
      if (!mass.inertia.isZero(0.0)) {
        out << YAML::Key << "inertia" << YAML::Value;
        writeInertia(out, mass.inertia);
      }
      if (!mass.offset.isZero(0.0)) {
        out << YAML::Key << "offset" << YAML::Value;
        vector(out, mass.offset);
      }
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }

  if (!model.rigid_joints.empty()) {
    out << YAML::Key << "rigid_joints" << YAML::Value << YAML::BeginSeq;
    for (const fem::RigidJoint& joint : model.rigid_joints) {
      out << YAML::Flow << YAML::BeginMap;
      if (!joint.name.empty()) {
        out << YAML::Key << "name" << YAML::Value;
        name(out, joint.name);
      }
      out << YAML::Key << "master" << YAML::Value << joint.master;
      out << YAML::Key << "slaves" << YAML::Value << YAML::Flow << YAML::BeginSeq;
      for (const NodeId slave : joint.slaves)
        out << slave;
      out << YAML::EndSeq << YAML::Key << "dofs" << YAML::Value << YAML::DoubleQuoted
          << dofDigits(joint.dofs) << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }

  if (!model.fixed.empty()) {
    out << YAML::Key << "fixed" << YAML::Value << YAML::BeginSeq;
    for (const fem::FixedDofs& fixed : model.fixed) {
      out << YAML::Flow << YAML::BeginMap << YAML::Key << "node" << YAML::Value << fixed.node
          << YAML::Key << "dofs" << YAML::Value << YAML::DoubleQuoted << dofDigits(fixed.dofs)
          << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }

  if (!model.ties.empty()) {
    out << YAML::Key << "ties" << YAML::Value << YAML::BeginSeq;
    for (const fem::Tie& tie : model.ties) {
      out << YAML::Flow << YAML::BeginMap;
      if (!tie.name.empty()) {
        out << YAML::Key << "name" << YAML::Value;
        name(out, tie.name);
      }
      out << YAML::Key << "nodes" << YAML::Value << YAML::Flow << YAML::BeginSeq << tie.n1 << tie.n2
          << YAML::EndSeq << YAML::Key << "force" << YAML::Value;
      number(out, tie.force);
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }

  if (!model.body_preloads.empty()) {
    out << YAML::Key << "body_preloads" << YAML::Value << YAML::BeginSeq;
    for (const fem::BodyPreload& body : model.body_preloads) {
      out << YAML::BeginMap;
      if (!body.name.empty()) {
        out << YAML::Key << "name" << YAML::Value;
        name(out, body.name);
      }
      out << YAML::Key << "node" << YAML::Value << body.node;
      out << YAML::Key << "points" << YAML::Value << YAML::BeginSeq;
      for (const Vector3& point : body.points)
        vector(out, point);
      out << YAML::EndSeq << YAML::Key << "forces" << YAML::Value << YAML::BeginSeq;
      for (const Vector3& force : body.forces)
        vector(out, force);
      out << YAML::EndSeq << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }

  if (!model.dof_sets.empty()) {
    out << YAML::Key << "sets" << YAML::Value << YAML::BeginMap;
    for (const auto& [set_name, dofs] : model.dof_sets) {
      out << YAML::Key;
      name(out, set_name);
      out << YAML::Value;
      if (dofs.empty())
        out << YAML::Flow;
      out << YAML::BeginSeq;
      for (const fem::DofRef& dof : dofs) {
        out << YAML::Flow << YAML::BeginMap << YAML::Key << "node" << YAML::Value << dof.node
            << YAML::Key << "dof" << YAML::Value << directionName(dof.direction) << YAML::EndMap;
      }
      out << YAML::EndSeq;
    }
    out << YAML::EndMap;
  }
}

}  // namespace

std::string formatModelYaml(const fem::Model& model) {
  YAML::Emitter out;
  out << YAML::Comment("Finite-element model (SI units); schema: doc/model_file.md")
      << YAML::Newline;
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value;
  name(out, model.name);
  out << YAML::Key << "gravity" << YAML::Value;
  vector(out, model.gravity);
  writeItems(out, model);
  out << YAML::EndMap;
  if (!out.good()) {
    throw Error("formatModelYaml: YAML emitter error: " + out.GetLastError());
  }
  return std::string(out.c_str()) + "\n";
}

void saveModelYaml(const fem::Model& model, const std::string& path) {
  const std::string text = formatModelYaml(model);
  AtomicTextFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
