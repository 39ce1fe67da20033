#include "dat_report.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <numeric>

#include <fmt/format.h>

namespace inpact::io {

namespace {

/// Values below this fraction of their column's largest magnitude print as zero (round-off
/// such as 4.3E-19 next to 1.5E-03 shows as 0.000 in Abaqus's printout).
constexpr double kZeroFraction = 1e-12;
constexpr int kWidth = 12;   ///< 1PG12.4
constexpr int kDigits = 4;

void pad_to(std::string& s, std::size_t column) {
  if (s.size() < column) s.append(column - s.size(), ' ');
}

std::string padded(std::string s, std::size_t column) {
  pad_to(s, column);
  return s;
}

}  // namespace

std::string fortran_g(double v, int width, int digits) {
  if (!std::isfinite(v)) return fmt::format("{:>{}}", std::isnan(v) ? "NaN" : v > 0 ? "Infinity" : "-Infinity", width);
  const double a = std::abs(v);
  // Gw.d: F editing with d significant digits (and 4 trailing blanks) when the rounded value
  // lies in [0.1, 10^d); E editing (here with the 1P scale factor: d.dddd E±xx) otherwise.
  if (a == 0.0) return fmt::format("{:>{}.{}f}    ", 0.0, width - 4, digits - 1);
  double lower = 0.1 - 0.5 * std::pow(10.0, -digits - 1);
  for (int k = 0; k <= digits; ++k) {
    const double upper = std::pow(10.0, k) - 0.5 * std::pow(10.0, k - digits);
    if (a >= lower && a < upper) {
      std::string f = fmt::format("{:.{}f}", v, digits - k);
      if (digits == k) f += '.';
      return fmt::format("{:>{}}    ", f, width - 4);
    }
    lower = upper;
  }
  return fmt::format("{:>{}}", fmt::format("{:.{}E}", v, digits), width);
}

std::string format_print_table(const PrintTable& t) {
  const bool element = t.domain == PrintTable::Domain::Element;
  const bool contact = t.domain == PrintTable::Domain::Contact;
  const std::size_t n = t.columns.size();
  const std::size_t n_rows = t.labels.size();
  const std::size_t prefix = element ? 24 : 15;  // label (+ point) and footnote columns
  std::string out;
  auto line = [&](const std::string& s) { out += s + '\n'; };

  // Title.
  if (contact) {
    line("   THE FOLLOWING TABLE IS PRINTED FOR THE SLAVE NODES OF CONTACT PAIR " + t.set);
  } else if (!element) {
    line(t.set.empty() ? "   THE FOLLOWING TABLE IS PRINTED FOR ALL NODES"
                       : "   THE FOLLOWING TABLE IS PRINTED FOR NODES BELONGING TO NODE SET " + t.set);
  } else {
    const std::string where = t.centroid ? "AT THE CENTROID OF THE ELEMENT" : "AT THE INTEGRATION POINTS";
    line(t.set.empty() ? fmt::format("   THE FOLLOWING TABLE IS PRINTED FOR ALL ELEMENTS WITH TYPE {} {}", t.element_type, where)
                       : fmt::format("   THE FOLLOWING TABLE IS PRINTED {} FOR ELEMENT TYPE {} AND ELEMENT SET {}", where,
                                     t.element_type, t.set));
  }
  line("");
  // Column header: each name 4 characters into its 12-character field.
  // A beam's or shell's section-point table has a SEC PT column after PT (Abaqus prints it the same way
  // as its FOOT-NOTE column, over two lines).
  const bool sections = element && t.at_section_points;
  std::string header = !element     ? "       NODE FOOT-"
                       : sections    ? (t.centroid ? "    ELEMENT     SEC FOOT-" : "    ELEMENT  PT SEC FOOT-")
                       : t.centroid  ? "    ELEMENT     FOOT-"
                                     : "    ELEMENT  PT FOOT-";
  for (std::size_t c = 0; c < n; ++c) {
    pad_to(header, prefix + kWidth * c + 4);
    header += t.columns[c];
  }
  pad_to(header, prefix + kWidth * n);
  line(header);
  line(sections ? "                 PT NOTE" : element ? "                NOTE" : "            NOTE");
  line("");

  // Values as printed: round-off next to the column's largest magnitude is zero.
  std::vector<double> largest(n, 0.0);
  for (std::size_t r = 0; r < n_rows; ++r)
    for (std::size_t c = 0; c < n; ++c) largest[c] = std::max(largest[c], std::abs(t.values[r * n + c]));
  auto shown = [&](std::size_t r, std::size_t c) {
    const double v = t.values[r * n + c];
    return std::abs(v) < kZeroFraction * largest[c] ? 0.0 : v;
  };
  std::vector<std::size_t> order(n_rows);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (t.labels[a] != t.labels[b]) return t.labels[a] < t.labels[b];
    if (!t.ip.empty() && t.ip[a] != t.ip[b]) return t.ip[a] < t.ip[b];
    return sections && t.section_point[a] < t.section_point[b];
  });
  auto values_of = [&](auto value) {
    std::string s;
    for (std::size_t c = 0; c < n; ++c) s += fortran_g(value(c), kWidth, kDigits);
    return s;
  };

  if (!t.totals_only) {
    for (std::size_t r : order) {
      bool all_zero = true;
      for (std::size_t c = 0; c < n; ++c) all_zero = all_zero && shown(r, c) == 0.0;
      if (all_zero) continue;  // Abaqus leaves rows of zeros out
      const std::string ip = t.ip.empty() ? std::string() : std::to_string(t.ip[r]);
      std::string row = !element  ? fmt::format("{:>11}    ", t.labels[r])
                        : sections ? fmt::format("{:>12}{:>4}{:>4}    ", t.labels[r], ip, t.section_point[r])
                                   : fmt::format("{:>12}{:>4}        ", t.labels[r], ip);
      line(row + values_of([&](std::size_t c) { return shown(r, c); }));
    }
    line("");
  }

  if (t.summary && !t.totals_only && n_rows > 0) {
    const std::string at = element ? " ELEMENT" : " AT NODE";
    for (const bool maximum : {true, false}) {
      std::vector<std::size_t> best(n, order.front());
      for (std::size_t c = 0; c < n; ++c)
        for (std::size_t r : order)
          if (maximum ? shown(r, c) > shown(best[c], c) : shown(r, c) < shown(best[c], c)) best[c] = r;
      line(padded(maximum ? " MAXIMUM" : " MINIMUM", prefix) + values_of([&](std::size_t c) { return shown(best[c], c); }));
      std::string where = padded(at, prefix);
      for (std::size_t c = 0; c < n; ++c) where += fmt::format("{:>11} ", t.labels[best[c]]);
      line(where);
      line("");
    }
  }
  if (t.totals) {
    line(padded(" TOTAL", prefix) + values_of([&](std::size_t c) {
           double sum = 0.0;
           for (std::size_t r = 0; r < n_rows; ++r) sum += t.values[r * n + c];
           return sum;
         }));
    line("");
  }
  return out;
}

DatReport::DatReport(std::filesystem::path path, const std::string& solver_version, const std::string& heading,
                     const std::string& solver_line)
    : path_(std::move(path)) {
  out_.open(path_, std::ios::out | std::ios::trunc);
  if (!out_) throw IoError(path_, "cannot create the data file");
  const std::time_t now = std::time(nullptr);
  char date[64] = "";
  std::strftime(date, sizeof date, "DATE %d-%b-%Y TIME %H:%M:%S", std::localtime(&now));
  std::string text = fmt::format("{:<42}{}\n", "inpact " + solver_version, date);
  if (!solver_line.empty()) text += solver_line + "\n";
  text += "\n";
  if (!heading.empty()) text += heading + "\n\n";
  put(text);
}

void DatReport::begin_step(const model::Step& step, int number) {
  put(fmt::format("\n\n                   S T E P{:>8}     S T A T I C   A N A L Y S I S\n\n\n          {}\n\n",
                  number, step.description.empty() ? step.name : step.description));
  if (step.nlgeom_switched_on) put(fmt::format("          {}\n\n", model::nlgeom_switched_on_note()));
}

void DatReport::contact_interactions(const std::vector<std::string>& lines) {
  if (lines.empty()) return;
  std::string text = "          CONTACT INTERACTIONS, AS ENFORCED IN THIS STEP\n\n";
  for (const std::string& line : lines) text += "     " + line + "\n";
  put(text + "\n");
}

void DatReport::write(const PrintFrame& frame) {
  const double fraction = frame.time_period > 0.0 ? frame.step_time / frame.time_period : 1.0;
  std::string text = fmt::format("\n                                INCREMENT{:>6} SUMMARY\n\n\n", frame.increment);
  text += fmt::format(" TIME INCREMENT COMPLETED {},  FRACTION OF STEP COMPLETED {}\n", fortran_g(frame.inc_of_time, 10, 3),
                      fortran_g(fraction, 10, 3));
  text += fmt::format(" STEP TIME COMPLETED      {},  TOTAL TIME COMPLETED       {}\n\n\n",
                      fortran_g(frame.step_time, 10, 3), fortran_g(frame.total_time, 10, 3));
  // Element output first, then node output, as Abaqus orders them.
  for (const auto domain : {PrintTable::Domain::Element, PrintTable::Domain::Node, PrintTable::Domain::Contact}) {
    bool first = true;
    for (const PrintTable& t : frame.tables) {
      if (t.domain != domain) continue;
      if (first) {
        text += domain == PrintTable::Domain::Element ? "                                   E L E M E N T   O U T P U T\n\n\n"
                : domain == PrintTable::Domain::Node  ? "                                       N O D E   O U T P U T\n\n\n"
                                                      : "                                 C O N T A C T   O U T P U T\n\n\n";
        first = false;
      }
      text += format_print_table(t) + "\n";
    }
  }
  put(text);
}

void DatReport::finish(bool completed) {
  put(completed ? "\n\n          THE ANALYSIS HAS BEEN COMPLETED\n" : "\n\n          THE ANALYSIS HAS NOT BEEN COMPLETED\n");
}

void DatReport::put(const std::string& text) {
  out_ << text;
  out_.flush();
  if (!out_) throw IoError(path_, "cannot write the data file");
}

}  // namespace inpact::io
