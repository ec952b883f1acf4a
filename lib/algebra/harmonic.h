// SPDX-License-Identifier: GPL-2.0-or-later
/** @file harmonic.h
 *  Harmonic polynomials: exact sparse sums of c · x^e · h(n·q), where c is a
 *  rational number, x^e a monomial in symbols (integer exponents), and h(n·q) is 1,
 *  cos(n·q) or sin(n·q) for an integer frequency vector n over the angles q whose
 *  first nonzero entry is positive. Products of harmonics are linearized by the
 *  product-to-sum formulas, so every term holds at most one harmonic: the canonical
 *  trigonometric form, in a representation that needs no GiNaC objects. */
#pragma once

#include <ginac/ginac.h>

#include <cln/rational.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace lagrange {

/// Which harmonic a term holds.
enum class wave : std::int32_t { none = 0, cos = 1, sin = 2 };

/// The variables of harmonic polynomials: the angles (in harmonics and as polynomial
/// variables) first, then the other symbols. A polynomial's terms are sized for the
/// symbols known when it was created; complete the space before making polynomials.
class harmonic_space {
public:
    /// Throws std::invalid_argument if an angle is not a symbol. Repeated angles count once.
    explicit harmonic_space(const GiNaC::lst& angles);

    /// Adds a symbol (a no-op if it is known) and returns its index. Throws
    /// std::invalid_argument if `symbol` is not a symbol.
    std::size_t add_symbol(const GiNaC::ex& symbol);

    /// Adds the symbols of `e`. False if `e` holds something that no harmonic
    /// polynomial can (a float, a constant such as Pi, a function other than sin and cos).
    bool add_symbols_of(const GiNaC::ex& e);

    std::optional<std::size_t> index_of(const GiNaC::ex& symbol) const;
    std::size_t angle_count() const { return angle_count_; }
    std::size_t symbol_count() const { return symbols_.size(); }
    const GiNaC::ex& symbol(std::size_t index) const { return symbols_[index]; }

    /// The GiNaC pieces of terms, each built once per space (the same object every time).
    /// cos(n·q) or sin(n·q), the argument built as GiNaC's sum of n_i·q_i; 1 for wave::none.
    const GiNaC::ex& wave_function(wave kind, const std::int32_t* frequency) const;
    /// symbol^exponent.
    const GiNaC::ex& power(std::size_t index, std::int32_t exponent) const;
    /// A coefficient as a GiNaC number.
    static GiNaC::ex number(const cln::cl_RA& c);

private:
    std::size_t angle_count_ = 0;
    GiNaC::exvector symbols_;
    std::unordered_multimap<unsigned, std::size_t> by_hash_;
    mutable std::unordered_map<std::uint64_t, std::vector<std::pair<std::vector<std::int32_t>, GiNaC::ex>>> waves_;
    mutable std::unordered_map<std::uint64_t, GiNaC::ex> powers_;
};

/// One term, as a view into a polynomial: coefficient · Π symbol^exponent · wave(frequency·angles).
struct harmonic_term {
    const cln::cl_RA* coefficient;
    wave kind;
    const std::int32_t* frequency; ///< one entry per angle
    const std::int32_t* exponents; ///< one entry per symbol of the space (when the polynomial was made)
};

/// A harmonic polynomial over a space: its terms in a flat table with a hash index.
class harmonic_polynomial {
public:
    /// The zero polynomial over `space`, which must outlive it.
    explicit harmonic_polynomial(const harmonic_space& space);

    /// The constant c.
    static harmonic_polynomial constant(const harmonic_space& space, const cln::cl_RA& c);
    /// The symbol of the given index.
    static harmonic_polynomial variable(const harmonic_space& space, std::size_t index);

    const harmonic_space& space() const { return *space_; }
    /// Number of (nonzero) terms.
    std::size_t size() const { return coefficients_.size(); }
    bool is_zero() const { return coefficients_.empty(); }
    harmonic_term term(std::size_t i) const;
    /// Number of symbols the exponent vectors cover.
    std::size_t symbol_count() const { return symbol_count_; }

    harmonic_polynomial& operator+=(const harmonic_polynomial& other);
    harmonic_polynomial& operator-=(const harmonic_polynomial& other);
    /// Multiplies every coefficient by c.
    harmonic_polynomial& operator*=(const cln::cl_RA& c);
    /// The product, linearized by the product-to-sum formulas.
    harmonic_polynomial operator*(const harmonic_polynomial& other) const;

    /// ∂/∂(symbol of the given index); for an angle this includes the harmonics.
    harmonic_polynomial derivative(std::size_t index) const;

    /// Σ ∂/∂s · r over the pairs (s, r) of symbol indices in `rates`, plus ∂/∂t if
    /// `time` is given: the total time derivative when q -> q̇, q̇ -> q̈.
    harmonic_polynomial total_derivative(const std::vector<std::pair<std::size_t, std::size_t>>& rates,
                                         std::optional<std::size_t> time) const;

private:
    friend struct harmonic_builder;

    /// Key layout: [wave, frequency (angle_count), exponents (symbol_count)].
    std::size_t key_size() const { return 1 + angle_count_ + symbol_count_; }
    const std::int32_t* key(std::size_t i) const { return keys_.data() + i * key_size(); }
    /// Adds c · key to the polynomial (coefficients may become zero; see prune).
    void add_term(const std::int32_t* key, const cln::cl_RA& c);
    /// Adds ∂(c·scratch)/∂(symbol `index`), times the symbol `rate` if given, where
    /// `scratch` is a key; restores `scratch` on return.
    void add_partial(std::vector<std::int32_t>& scratch, const cln::cl_RA& c, std::size_t index,
                     std::optional<std::size_t> rate);
    /// Removes zero terms.
    void prune();
    void check_same_space(const harmonic_polynomial& other) const;
    void grow_table();

    const harmonic_space* space_;
    std::size_t angle_count_;
    std::size_t symbol_count_;
    std::vector<std::int32_t> keys_;
    std::vector<cln::cl_RA> coefficients_;
    std::vector<std::uint64_t> hashes_;
    std::vector<std::uint32_t> table_; ///< open addressing: 0 empty, else term index + 1
};

/// `e` as a harmonic polynomial over `space`, or nullopt if it is not one: sums,
/// products, integer powers (negative ones only of symbols other than the angles),
/// rational numbers, known symbols, and sin/cos of integer combinations of the
/// angles without constant offset.
std::optional<harmonic_polynomial> to_harmonic(const GiNaC::ex& e, const harmonic_space& space);

/// The expanded GiNaC expression: Σ c · Π symbol^exponent · cos/sin(n·q), the
/// argument n·q built as GiNaC's sum of n_i·q_i.
GiNaC::ex to_ex(const harmonic_polynomial& p);

} // namespace lagrange
