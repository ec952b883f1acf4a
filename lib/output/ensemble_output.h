// SPDX-License-Identifier: GPL-2.0-or-later
/** @file ensemble_output.h
 *  Writers of an ensemble's rows as they arrive: CSV (one row per point, grid order),
 *  JSON (one object whose `ensemble.rows` array is written row by row), and a PNG map of a
 *  2-D grid drawn by gnuplot; and the check that lets an interrupted CSV run resume. Numbers
 *  are the shortest decimals that read back as the same double (std::to_chars), so the
 *  output is byte-identical for any number of threads and processes. */
#pragma once

#include "ensemble/run.h"

#include <fstream>
#include <memory>
#include <ostream>
#include <string>

namespace lagrange {

class private_directory;

/// CSV: a header line of column names, then one line per point; `inf` where a point never
/// flipped, `nan` where its integration failed.
void write_ensemble_csv_header(std::ostream& out, const ensemble_problem& problem);
void write_ensemble_csv_row(std::ostream& out, const ensemble_problem& problem, const double* row);

/// JSON: `{"ensemble": {"columns": [...], "rows": [[...], …], "steps": N, "failures": N,
/// "error_estimate": {...}}}`; null where CSV has inf or nan.
void write_ensemble_json_begin(std::ostream& out, const ensemble_problem& problem);
void write_ensemble_json_row(std::ostream& out, const ensemble_problem& problem, std::size_t index, const double* row);
void write_ensemble_json_end(std::ostream& out, const ensemble_problem& problem, const ensemble_summary& summary);

/// --resume: checks that the CSV file at `path` was written by the same ensemble (its header,
/// and the grid values of its last complete row), cuts off a last line left incomplete, and
/// returns the number of complete rows (the point to go on from). A missing or empty file: 0.
/// Throws file_error when the file belongs to another ensemble.
std::size_t resume_ensemble_csv(const std::string& path, const ensemble_problem& problem);

/// The map of a 2-D grid: rows collected into a data file, then drawn by gnuplot as a PNG
/// with a colour scale (logarithmic for flip times; points that never flip left white) and
/// the grid's names on the axes.
class ensemble_map {
public:
    /// Throws computation_error unless the ensemble is a 2-D grid.
    explicit ensemble_map(const ensemble_problem& problem);
    ~ensemble_map();
    void row(const double* row);
    /// Draws the PNG into `path`; throws computation_error without gnuplot.
    void draw(const std::string& path, const std::string& title);

private:
    const ensemble_problem& problem_;
    std::unique_ptr<private_directory> folder_;
    std::ofstream data_;
    double previous_x_ = 0;
    bool first_ = true;
    double low_ = 0, high_ = 0; ///< range of the finite values drawn
    bool any_ = false;
};

/// The summary for the terminal: points, rate, steps, failures and the error estimate.
std::string ensemble_summary_text(const ensemble_problem& problem, const ensemble_summary& summary,
                                  const std::string& first_failure_message);

} // namespace lagrange
