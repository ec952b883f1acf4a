// SPDX-License-Identifier: GPL-2.0-or-later
/** @file export_program.h
 *  What the exported targets share (export_code.cpp): each target's names for the program
 *  symbols, where the generated functions' arguments hold them, one program written line by
 *  line in the target's syntax, and the header comment. Internal to output/. */
#pragma once

#include "output/export_code.h"

#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace lagrange::export_detail {

enum class dialect { c, python, octave };

/// The words a target reserves (its keywords and the functions the generated code calls).
const std::set<std::string>& keywords(dialect d);

/// The names of one target: each program symbol's (q, q̇, t, p, u), with `_` appended to a
/// name the target reserves (a keyword, or an argument of the generated functions), and the
/// prefix of temporaries, chosen to differ from every name.
struct naming {
    std::vector<std::string> symbols;
    std::vector<std::pair<std::string, std::string>> renamed;
    std::string temporary = "v";
};
naming name_symbols(const exported_system& system, dialect d);

/// Where exported function arguments hold program symbol k: the array (`x`, `p` or `u`; `t`
/// for time) and the 0-based index in it.
struct argument_place {
    char array;
    int index;
};
argument_place place_of(int k, const exported_system& system);

/// One program as straight-line code: `lines` gets an assignment per instruction that an
/// output reads and that is neither a symbol nor a constant (those are written where they are
/// used); returns the text of each output. `used` gets the index of every symbol it reads.
std::vector<std::string> write_program(const expression_program& program, dialect d, const naming& names,
                                       const std::string& indent, std::ostringstream& lines, std::set<int>& used);

/// Whether the C code of `program` calls lagrange_sincos2 (it takes the sines and cosines of
/// two or more symbols).
bool takes_sincos_pairs(const expression_program& program);

/// What the header comment of every file says: where the code came from, the orders, the units
/// and the renamed names, each line starting with `comment`.
std::string provenance(const model& scene, const exported_system& system, const naming& names,
                       const std::string& version, const std::string& comment);

/// The numbers as a comma-separated list of shortest decimals, `nan` for a NaN.
std::string number_list(const std::vector<double>& values, const char* nan);

/// Each target's files (see export_code()).
std::vector<exported_file> export_c(const model& scene, const exported_system& system, const std::string& name,
                                    const std::string& version);
std::vector<exported_file> export_python(const model& scene, const exported_system& system, const std::string& name,
                                         const std::string& version);
std::vector<exported_file> export_octave(const model& scene, const exported_system& system, const std::string& name,
                                         const std::string& version);

} // namespace lagrange::export_detail
