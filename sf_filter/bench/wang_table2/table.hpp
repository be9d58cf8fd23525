// Table II of Wang et al. (the paper's numbers) and the same table measured by Monte Carlo:
// per method and vision noise column the variance and rms of the estimation error, averaged
// over the runs, and the change of each method against the Kalman filter on the same runs.
#pragma once

#include <array>
#include <cstddef>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>

#include "error_statistics.hpp"
#include "methods.hpp"
#include "parameters.hpp"

namespace wang_table2 {

constexpr std::size_t kColumns = kVisionStds.size();
constexpr std::size_t kRows = 3;  // Kalman filter, multi-rate hold, filling: kMethods' order

struct Figure {
  double variance = 0.0;
  double rms = 0.0;
};

/// Table II as printed in the paper (sigma_b = 0.2 m).
constexpr std::array<std::array<Figure, kColumns>, kRows> kPaperTable = {{
    {{{0.00068, 0.02620},
      {0.00249, 0.04988},
      {0.00423, 0.06505},
      {0.00562, 0.07503},
      {0.00708, 0.08431}}},
    {{{0.00063, 0.02499},
      {0.00230, 0.04797},
      {0.00389, 0.06244},
      {0.00597, 0.07732},
      {0.00789, 0.08898}}},
    {{{0.00054, 0.02328},
      {0.00187, 0.04325},
      {0.00342, 0.05849},
      {0.00541, 0.07358},
      {0.00706, 0.08416}}},
}};

/// One run's error series, per method (kMethods' order) and column.
using RunErrors = std::array<std::array<ErrorSeries, kColumns>, kRows>;

class MeasuredTable {
 public:
  void addRun(const RunErrors& run) {
    for (std::size_t m = 0; m < kRows; ++m) {
      for (std::size_t c = 0; c < kColumns; ++c) {
        variance_[m][c].add(run[m][c].variance());
        rms_[m][c].add(run[m][c].rms());
        varianceChange_[m][c].add(run[0][c].variance(), run[m][c].variance());
        rmsChange_[m][c].add(run[0][c].rms(), run[m][c].rms());
      }
    }
  }

  std::size_t runs() const { return variance_[0][0].runs(); }
  const RunAverage& variance(std::size_t method, std::size_t column) const {
    return variance_[method][column];
  }
  const RunAverage& rms(std::size_t method, std::size_t column) const {
    return rms_[method][column];
  }
  /// The change of `method`'s figure against the Kalman filter's (row 0) on the same runs.
  const PairedChange& varianceChange(std::size_t method, std::size_t column) const {
    return varianceChange_[method][column];
  }
  const PairedChange& rmsChange(std::size_t method, std::size_t column) const {
    return rmsChange_[method][column];
  }

 private:
  template <class T>
  using Grid = std::array<std::array<T, kColumns>, kRows>;
  Grid<RunAverage> variance_, rms_;
  Grid<PairedChange> varianceChange_, rmsChange_;
};

/// The paper's relative change of `method` against the Kalman filter, (b - a) / a.
inline Figure paperChange(std::size_t method, std::size_t column) {
  const Figure& a = kPaperTable[0][column];
  const Figure& b = kPaperTable[method][column];
  return {(b.variance - a.variance) / a.variance, (b.rms - a.rms) / a.rms};
}

namespace table_detail {

constexpr int kLabel = 30;  // method and source
constexpr int kCell = 10;   // one number

inline void header(std::ostream& out) {
  out << std::left << std::setw(kLabel) << "(sigma_b = 0.2 m)" << std::right;
  for (double s : kVisionStds) {
    std::ostringstream column;
    column << "sigma_u " << std::fixed << std::setprecision(3) << s << " m";
    out << std::setw(2 * kCell + 2) << column.str();
  }
  out << '\n' << std::left << std::setw(kLabel) << "method / source" << std::right;
  for (std::size_t c = 0; c < kColumns; ++c) {
    out << "  " << std::setw(kCell) << "var" << std::setw(kCell) << "rms";
  }
  out << '\n';
}

template <class Cell>
void row(std::ostream& out, const std::string& label, int precision, bool percent, Cell cell) {
  out << std::left << std::setw(kLabel) << label << std::right << std::fixed
      << std::setprecision(precision);
  const double scale = percent ? 100.0 : 1.0;
  for (std::size_t c = 0; c < kColumns; ++c) {
    const Figure f = cell(c);
    out << "  " << std::setw(kCell) << f.variance * scale << std::setw(kCell) << f.rms * scale;
  }
  out << '\n';
}

}  // namespace table_detail

/// Prints the measured table beside the paper's: per method the run means, their standard
/// errors and the paper's figures, then the change of the hold and the filling against the
/// Kalman filter in percent (measured on the same runs, with standard errors, and the paper's).
inline void printTable(std::ostream& out, const MeasuredTable& t) {
  using table_detail::row;
  table_detail::header(out);
  for (std::size_t m = 0; m < kRows; ++m) {
    const std::string name = nameOf(kMethods[m]);
    row(out, name + "  measured", 5, false, [&](std::size_t c) {
      return Figure{t.variance(m, c).mean(), t.rms(m, c).mean()};
    });
    row(out, "    std. error", 5, false, [&](std::size_t c) {
      return Figure{t.variance(m, c).standardError(), t.rms(m, c).standardError()};
    });
    row(out, "    paper", 5, false, [&](std::size_t c) { return kPaperTable[m][c]; });
  }
  out << "change against the Kalman filter [%] (same runs):\n";
  for (std::size_t m = 1; m < kRows; ++m) {
    const std::string name = nameOf(kMethods[m]);
    row(out, name + "  measured", 1, true, [&](std::size_t c) {
      return Figure{t.varianceChange(m, c).relative(), t.rmsChange(m, c).relative()};
    });
    row(out, "    std. error", 1, true, [&](std::size_t c) {
      return Figure{t.varianceChange(m, c).standardError(), t.rmsChange(m, c).standardError()};
    });
    row(out, "    paper", 1, true, [&](std::size_t c) { return paperChange(m, c); });
  }
}

}  // namespace wang_table2
