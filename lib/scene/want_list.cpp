// SPDX-License-Identifier: GPL-2.0-or-later
/** @file want_list.cpp
 *  The `want` list given on the command line (`--want equations,modes`; see lower.h). */
#include "scene/lower.h"

#include "scene/lexer.h"

#include <sstream>

namespace lagrange {

std::set<product> parse_want_list(const std::string& text)
{
    std::set<product> wanted;
    std::stringstream items(text);
    std::string item;
    int column = 1;
    while (std::getline(items, item, ',')) {
        std::size_t first = item.find_first_not_of(' ');
        std::size_t last = item.find_last_not_of(' ');
        std::string name = first == std::string::npos ? "" : item.substr(first, last - first + 1);
        std::optional<product> p = product_from_name(name);
        if (!p) {
            std::string all;
            for (const auto& [unused, n] : product_names())
                all += (all.empty() ? "" : ", ") + n;
            scene_error error({"--want", 1, column + static_cast<int>(first == std::string::npos ? 0 : first)},
                              "unknown product " + quote(name) + "; the products are: " + all);
            error.attach_line_text(text);
            throw error;
        }
        wanted.insert(*p);
        column += static_cast<int>(item.size()) + 1;
    }
    return wanted;
}

} // namespace lagrange
