// SPDX-License-Identifier: GPL-2.0-or-later
/** @file expression.cpp
 *  The expression helpers of expression.h that are not inline. */
#include "algebra/expression.h"

#include <typeinfo>
#include <utility>

namespace lagrange {

ex_kind ex_kind_of(const GiNaC::ex& e)
{
    // The type_info objects of GiNaC's classes live in libginac, so comparing their
    // addresses is exact for these classes; anything else takes the slow path.
    static const std::pair<const std::type_info*, ex_kind> known[] = {
        {&typeid(GiNaC::add), ex_kind::sum},
        {&typeid(GiNaC::mul), ex_kind::product},
        {&typeid(GiNaC::numeric), ex_kind::number},
        {&typeid(GiNaC::power), ex_kind::power},
        {&typeid(GiNaC::function), ex_kind::function},
        {&typeid(GiNaC::realsymbol), ex_kind::symbol},
        {&typeid(GiNaC::possymbol), ex_kind::symbol},
        {&typeid(GiNaC::symbol), ex_kind::symbol},
        {&typeid(GiNaC::wildcard), ex_kind::wildcard},
        {&typeid(GiNaC::constant), ex_kind::constant},
    };
    const GiNaC::basic& object = GiNaC::ex_to<GiNaC::basic>(e);
    const std::type_info* type = &typeid(object);
    for (const auto& [known_type, kind] : known)
        if (type == known_type)
            return kind;
    if (GiNaC::is_a<GiNaC::add>(e))
        return ex_kind::sum;
    if (GiNaC::is_a<GiNaC::mul>(e))
        return ex_kind::product;
    if (GiNaC::is_a<GiNaC::numeric>(e))
        return ex_kind::number;
    if (GiNaC::is_a<GiNaC::power>(e))
        return ex_kind::power;
    if (GiNaC::is_a<GiNaC::function>(e))
        return ex_kind::function;
    if (GiNaC::is_a<GiNaC::symbol>(e))
        return ex_kind::symbol;
    if (GiNaC::is_a<GiNaC::wildcard>(e))
        return ex_kind::wildcard;
    if (GiNaC::is_a<GiNaC::constant>(e))
        return ex_kind::constant;
    return ex_kind::other;
}

GiNaC::exvector terms_of(const GiNaC::ex& e)
{
    GiNaC::exvector terms;
    if (ex_kind_of(e) == ex_kind::sum) {
        terms.reserve(e.nops());
        for (size_t i = 0; i < e.nops(); ++i)
            terms.push_back(e.op(i));
    } else if (!e.is_zero()) {
        terms.push_back(e);
    }
    return terms;
}

GiNaC::exvector factors_of(const GiNaC::ex& e)
{
    GiNaC::exvector factors;
    if (ex_kind_of(e) == ex_kind::product) {
        factors.reserve(e.nops());
        for (size_t i = 0; i < e.nops(); ++i)
            factors.push_back(e.op(i));
    } else {
        factors.push_back(e);
    }
    return factors;
}

bool has_symbol(const GiNaC::ex& e)
{
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
        if (GiNaC::is_a<GiNaC::symbol>(*i))
            return true;
    return false;
}

bool is_sin_or_cos(const GiNaC::ex& e)
{
    return GiNaC::is_the_function<GiNaC::sin_SERIAL>(e) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(e);
}

bool has_trigonometric(const GiNaC::ex& e)
{
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
        if (is_sin_or_cos(*i) || GiNaC::is_the_function<GiNaC::tan_SERIAL>(*i))
            return true;
    return false;
}

bool inside_trigonometric(const GiNaC::ex& e, const GiNaC::ex& q)
{
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
        if (is_sin_or_cos(*i) && i->op(0).has(q))
            return true;
    return false;
}

bool inside_function(const GiNaC::ex& e, const GiNaC::ex& q)
{
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
        if (GiNaC::is_a<GiNaC::function>(*i) && i->has(q))
            return true;
    return false;
}

bool has_compound_denominator(const GiNaC::ex& e)
{
    if (ex_kind_of(e) == ex_kind::sum || ex_kind_of(e) == ex_kind::product) {
        for (size_t i = 0; i < e.nops(); ++i)
            if (has_compound_denominator(e.op(i)))
                return true;
        return false;
    }
    if (ex_kind_of(e) == ex_kind::power)
        return e.op(1).info(GiNaC::info_flags::negint) && ex_kind_of(e.op(0)) != ex_kind::symbol;
    return false;
}

} // namespace lagrange
