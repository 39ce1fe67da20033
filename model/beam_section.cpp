#include "beam_section_area.hpp"

#include <numbers>

namespace inpact::model {

double section_area(const BeamSection& s) {
  const auto& d = s.dims;
  switch (s.shape) {
    case BeamSection::Shape::Rect: return d[0] * d[1];
    case BeamSection::Shape::Circ: return std::numbers::pi * s.circ_semi_axes()[0] * s.circ_semi_axes()[1];
    case BeamSection::Shape::Pipe: return std::numbers::pi * (d[0] * d[0] - (d[0] - d[1]) * (d[0] - d[1]));
    case BeamSection::Shape::Box: return d[0] * d[1] - (d[0] - d[2] - d[4]) * (d[1] - d[3] - d[5]);
    case BeamSection::Shape::I: return d[2] * d[4] + d[3] * d[5] + (d[1] - d[4] - d[5]) * d[6];
    case BeamSection::Shape::General: return d[0];
  }
  return 0.0;
}

const char* shape_name(BeamSection::Shape shape) {
  switch (shape) {
    case BeamSection::Shape::Rect: return "RECT";
    case BeamSection::Shape::Circ: return "CIRC";
    case BeamSection::Shape::Pipe: return "PIPE";
    case BeamSection::Shape::Box: return "BOX";
    case BeamSection::Shape::I: return "I";
    case BeamSection::Shape::General: return "GENERAL";
  }
  return "?";
}

}  // namespace inpact::model
