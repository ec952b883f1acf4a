/** @file message_text.cpp
 *  Expressions as sorted text for messages (see message_text.h). */
#include "algebra/message_text.h"

#include <algorithm>
#include <sstream>
#include <vector>

namespace lagrange {

namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;

std::string print(const ex& e)
{
    std::ostringstream out;
    out << e;
    return out.str();
}

} // namespace

std::string message_text(const ex& e)
{
    auto wrapped = [](const ex& x) {
        std::string text = message_text(x);
        return is_a<GiNaC::add>(x) || is_a<GiNaC::mul>(x) ? "(" + text + ")" : text;
    };
    if (is_a<GiNaC::mul>(e) && e.op(e.nops() - 1).is_equal(-1)) { // −x, not -1*x
        ex positive = -e;
        return "-" + (is_a<GiNaC::add>(positive) ? "(" + message_text(positive) + ")" : message_text(positive));
    }
    if (is_a<GiNaC::add>(e) || is_a<GiNaC::mul>(e)) {
        std::vector<std::string> parts;
        for (const ex& operand : e)
            parts.push_back(is_a<GiNaC::add>(e) ? message_text(operand) : wrapped(operand));
        std::sort(parts.begin(), parts.end());
        std::string out;
        if (is_a<GiNaC::mul>(e) && parts.size() > 1 && parts.front() == "-1") { // -E*q0, not -1*E*q0
            parts.erase(parts.begin());
            out = "-";
        }
        for (const std::string& part : parts)
            out += (out.empty() || out == "-" ? "" : (is_a<GiNaC::add>(e) ? (part.rfind('-', 0) == 0 ? "" : "+") : "*")) +
                   part;
        return out;
    }
    if (is_a<GiNaC::power>(e))
        return wrapped(e.op(0)) + "^" + wrapped(e.op(1));
    if (is_a<GiNaC::function>(e)) {
        std::string out = ex_to<GiNaC::function>(e).get_name() + "(";
        for (std::size_t i = 0; i < e.nops(); ++i)
            out += (i ? "," : "") + message_text(e.op(i));
        return out + ")";
    }
    return print(e);
}

} // namespace lagrange
