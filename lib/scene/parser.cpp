// SPDX-License-Identifier: GPL-2.0-or-later
/** @file parser.cpp
 *  The scene grammar, one function per rule (the rule is in the comment above it).
 *  No names are resolved here: that is the semantic checks' job. */
#include "scene/parser.h"

#include <set>

namespace lagrange {

const std::set<std::string>& function_names()
{
    static const std::set<std::string> names = {"sin", "cos", "tan", "exp", "log", "sqrt", "sinh",
                                                 "cosh", "tanh", "asin", "acos", "atan", "abs"};
    return names;
}

namespace {

class parser {
public:
    explicit parser(const std::vector<token>& tokens) : tokens_(tokens) {}

    // scene := { [statement] NEWLINE } END
    scene_ast parse_scene()
    {
        scene_ast scene;
        while (!at(token_kind::end)) {
            if (accept(token_kind::newline))
                continue;
            scene.statements.push_back(parse_statement());
            expect_end_of_statement();
        }
        return scene;
    }

    // rules := { [expr '->' expr] NEWLINE } END
    std::vector<parsed_rule> parse_rules()
    {
        std::vector<parsed_rule> rules;
        while (!at(token_kind::end)) {
            if (accept(token_kind::newline))
                continue;
            parsed_rule rule;
            rule.where = current().where;
            rule.pattern = parse_expr();
            expect(token_kind::arrow, "`->` between the pattern and its replacement");
            rule.replacement = parse_expr();
            expect_end_of_statement();
            rules.push_back(std::move(rule));
        }
        return rules;
    }

private:
    // ---- token access -------------------------------------------------------
    const token& current() const { return tokens_[pos_]; }
    bool at(token_kind kind) const { return current().kind == kind; }
    bool at_name(const char* text) const { return at(token_kind::name) && current().text == text; }

    const token& take()
    {
        const token& t = tokens_[pos_];
        if (t.kind != token_kind::end)
            ++pos_;
        return t;
    }

    bool accept(token_kind kind)
    {
        if (!at(kind))
            return false;
        take();
        return true;
    }

    bool accept_name(const char* text)
    {
        if (!at_name(text))
            return false;
        take();
        return true;
    }

    [[noreturn]] void fail_here(const std::string& wanted) const
    {
        const token& t = current();
        // `sin th`: a function name followed by its argument without parentheses.
        const bool operand = t.kind == token_kind::name || t.kind == token_kind::integer ||
                             t.kind == token_kind::decimal;
        if (operand && pos_ > 0 && tokens_[pos_ - 1].kind == token_kind::name &&
            function_names().count(tokens_[pos_ - 1].text))
            throw scene_error(t.where, "a function's argument goes in parentheses: write `" +
                                           tokens_[pos_ - 1].text + "(" + t.text + ")`");
        std::string found = t.kind == token_kind::name ? quote(t.text)
                          : (t.kind == token_kind::integer || t.kind == token_kind::decimal)
                              ? "the number " + quote(t.text)
                              : describe(t.kind);
        throw scene_error(t.where, "expected " + wanted + ", found " + found);
    }

    const token& expect(token_kind kind, const std::string& wanted)
    {
        if (!at(kind))
            fail_here(wanted);
        return take();
    }

    void expect_keyword(const char* keyword)
    {
        if (!accept_name(keyword))
            fail_here(std::string("`") + keyword + "`");
    }

    name_ref expect_name(const std::string& what)
    {
        const token& t = expect(token_kind::name, what);
        return {t.text, t.where};
    }

    void expect_end_of_statement()
    {
        if (!at(token_kind::newline) && !at(token_kind::end))
            fail_here("the end of the statement");
        accept(token_kind::newline);
    }

    // ---- statements -----------------------------------------------------------

    // statement := scene | parameters | coordinates | let | energy | point | gravity
    //            | spring | body | omega | torque | equilibrium | ratio | limit
    //            | values | initial | simulate | use | want
    //            | dissipation | damper | force | input | constraint | linearize | independent
    //            | critical | rolls
    statement parse_statement()
    {
        const token& first = current();
        if (first.kind != token_kind::name)
            fail_here("a statement (`parameters`, `coordinates`, `T = ...`, `point`, ...)");
        statement s;
        s.keyword = first.text;
        s.where = first.where;
        const std::string& k = first.text;
        if ((k == "T" || k == "V" || k == "L") && tokens_[pos_ + 1].kind == token_kind::equals) {
            take();
            take();
            s.value = parse_expr();
            return s;
        }
        take();
        if (k == "scene") parse_scene_title(s);
        else if (k == "parameters" || k == "coordinates") parse_name_list(s, k);
        else if (k == "let") parse_let(s);
        else if (k == "point") parse_point(s);
        else if (k == "gravity") parse_gravity(s);
        else if (k == "spring") parse_spring(s);
        else if (k == "body") parse_body(s);
        else if (k == "omega" || k == "torque") parse_body_vector(s);
        else if (k == "equilibrium" || k == "values" || k == "initial") parse_assignments(s);
        else if (k == "ratio") parse_ratio(s);
        else if (k == "limit") parse_limit(s);
        else if (k == "simulate") parse_simulate(s);
        else if (k == "use") parse_use(s);
        else if (k == "want") parse_want(s);
        else if (k == "dissipation") parse_dissipation(s);
        else if (k == "damper") parse_damper(s);
        else if (k == "force") parse_force(s);
        else if (k == "input") parse_name_list(s, k);
        else if (k == "constraint") parse_constraint(s);
        else if (k == "linearize") parse_linearize(s);
        else if (k == "independent") parse_independent(s);
        else if (k == "critical") parse_critical(s);
        else if (k == "rolls") parse_rolls(s);
        else
            throw scene_error(first.where, "unknown statement " + quote(k));
        return s;
    }

    // scene_title := 'scene' STRING
    void parse_scene_title(statement& s) { s.text = expect(token_kind::string, "a title in quotes").text; }

    // name_list := ('parameters' | 'coordinates' | 'input') NAME { NAME }
    void parse_name_list(statement& s, const std::string& keyword)
    {
        s.names.push_back(expect_name("a name after `" + keyword + "`"));
        while (at(token_kind::name))
            s.names.push_back(expect_name("a name"));
    }

    // let := 'let' NAME '=' expr
    void parse_let(statement& s)
    {
        s.names.push_back(expect_name("the name of the shorthand"));
        expect(token_kind::equals, "`=`");
        s.value = parse_expr();
    }

    // point := 'point' NAME 'mass' expr 'at' vector
    void parse_point(statement& s)
    {
        s.names.push_back(expect_name("the point's name"));
        expect_keyword("mass");
        s.value = parse_expr();
        expect_keyword("at");
        s.vector = parse_vector();
    }

    // gravity := 'gravity' expr 'along' vector
    void parse_gravity(statement& s)
    {
        s.value = parse_expr();
        expect_keyword("along");
        s.vector = parse_vector();
    }

    // spring := 'spring' expr 'between' endpoint 'and' endpoint [ 'rest' expr ]
    void parse_spring(statement& s)
    {
        s.value = parse_expr();
        expect_keyword("between");
        s.end_a = parse_endpoint();
        expect_keyword("and");
        s.end_b = parse_endpoint();
        if (accept_name("rest"))
            s.rest = parse_expr();
    }

    // dissipation := 'dissipation' 'F' '=' expr
    void parse_dissipation(statement& s)
    {
        if (!at_name("F"))
            fail_here("`F`, the Rayleigh function, as in `dissipation F = 1/2*b*x'^2`");
        take();
        expect(token_kind::equals, "`=`");
        s.value = parse_expr();
    }

    // damper := 'damper' expr 'between' endpoint 'and' endpoint
    void parse_damper(statement& s)
    {
        s.value = parse_expr();
        expect_keyword("between");
        s.end_a = parse_endpoint();
        expect_keyword("and");
        s.end_b = parse_endpoint();
    }

    // force := 'force' ( 'on' NAME vector | NAME '=' expr )
    void parse_force(statement& s)
    {
        if (at_name("on") && tokens_[pos_ + 1].kind != token_kind::equals) {
            take();
            s.on_point = true;
            s.names.push_back(expect_name("the name of the point the force acts on"));
            s.vector = parse_vector();
            return;
        }
        s.names.push_back(expect_name("a coordinate, as in `force x = -c*x'`, or `on` and a point"));
        expect(token_kind::equals, "`=`");
        s.value = parse_expr();
    }

    // constraint := 'constraint' NAME ':' expr '=' expr
    void parse_constraint(statement& s)
    {
        s.names.push_back(expect_name("the constraint's name, as in `constraint rope: y1 + y2 = -l`"));
        expect(token_kind::colon, "`:` after the constraint's name");
        s.value = parse_expr();
        expect(token_kind::equals, "`=` between the two sides of the constraint");
        s.right = parse_expr();
    }

    // endpoint := NAME | vector
    endpoint parse_endpoint()
    {
        endpoint e;
        if (at(token_kind::name))
            e.point = expect_name("a point");
        else
            e.position = parse_vector();
        return e;
    }

    // body := 'body' NAME ( SHAPE '(' args ')' 'mass' expr
    //                     | 'region' REGION '(' args ')' 'density' expr
    //                     | 'inertia' ( vector | tensor ) 'mass' expr ) { body_option }
    void parse_body(statement& s)
    {
        body_statement b;
        b.name = expect_name("the body's name");
        if (accept_name("region")) {
            b.body_kind = body_statement::kind::region;
            b.shape = parse_shape("a region such as `ball(R)`");
            expect_keyword("density");
            b.density = parse_expr();
        } else if (accept_name("inertia")) {
            b.body_kind = body_statement::kind::inertia;
            if (at_tensor())
                parse_tensor(b);
            else
                b.moments = parse_vector();
            expect_keyword("mass");
            b.mass = parse_expr();
        } else {
            b.shape = parse_shape("a shape such as `disk(R)`, `region` or `inertia`");
            expect_keyword("mass");
            b.mass = parse_expr();
        }
        parse_body_options(b);
        s.body = std::move(b);
    }

    /// Whether a tensor `((…, …), …)` starts here: `((` whose inner parenthesis holds a
    /// comma at its own depth (`((a + b), c, d)` is a vector).
    bool at_tensor() const
    {
        if (!at(token_kind::left_paren) || tokens_[pos_ + 1].kind != token_kind::left_paren)
            return false;
        int depth = 0;
        for (std::size_t k = pos_ + 1; tokens_[k].kind != token_kind::end; ++k) {
            const token_kind kind = tokens_[k].kind;
            if (kind == token_kind::left_paren)
                ++depth;
            else if (kind == token_kind::right_paren && --depth == 0)
                return false;
            else if (kind == token_kind::comma && depth == 1)
                return true;
            else if (kind == token_kind::newline)
                return false;
        }
        return false;
    }

    // tensor := '(' vector { ',' vector } ')'
    void parse_tensor(body_statement& b)
    {
        b.tensor_where = current().where;
        expect(token_kind::left_paren, "`(` to start the tensor");
        b.tensor_rows.push_back(parse_vector());
        while (accept(token_kind::comma)) {
            if (b.tensor_rows.size() == 3)
                throw scene_error(tokens_[pos_ - 1].where, "an inertia tensor has three rows");
            b.tensor_rows.push_back(parse_vector());
        }
        expect(token_kind::right_paren, "`)` to close the tensor");
    }

    // rotations := 'rotations' '(' NAME expr { ',' NAME expr } ')'
    shape_expr parse_rotations(body_statement& b)
    {
        shape_expr rotations;
        rotations.name = expect_name("`rotations`");
        expect(token_kind::left_paren, "`(` after `rotations`");
        do {
            b.rotation_axes.push_back(expect_name("an axis `x`, `y` or `z` before the angle"));
            rotations.arguments.push_back(parse_expr());
        } while (accept(token_kind::comma));
        expect(token_kind::right_paren, "`)`");
        return rotations;
    }

    // body_option := 'axis' NAME | 'at' vector | 'orientation' ( NAME '(' args ')' | rotations )
    //              | 'about' vector | 'attached' 'to' NAME
    void parse_body_options(body_statement& b)
    {
        std::set<std::string> seen;
        while (at(token_kind::name)) {
            const token& option = current();
            if (!seen.insert(option.text).second)
                throw scene_error(option.where, quote(option.text) + " is given twice");
            if (accept_name("axis"))
                b.axis = expect_name("`x`, `y` or `z`");
            else if (accept_name("at"))
                b.at = parse_vector();
            else if (accept_name("orientation"))
                b.orientation = at_name("rotations") ? parse_rotations(b)
                                                     : parse_shape("`zxz(phi, theta, psi)` or `rotations(z q1, x q2, ...)`");
            else if (accept_name("about"))
                b.about = parse_vector();
            else if (accept_name("attached")) {
                expect_keyword("to");
                b.attached_to = expect_name("the name of a body");
            } else
                fail_here("`axis`, `at`, `orientation`, `about`, `attached to` or the end of the statement");
        }
    }

    // shape := NAME '(' expr { ',' expr } ')'
    shape_expr parse_shape(const std::string& what)
    {
        shape_expr shape;
        shape.name = expect_name(what);
        expect(token_kind::left_paren, "`(` after `" + shape.name.name + "`");
        shape.arguments.push_back(parse_expr());
        while (accept(token_kind::comma))
            shape.arguments.push_back(parse_expr());
        expect(token_kind::right_paren, "`)`");
        return shape;
    }

    // body_vector := ('omega' | 'torque') NAME vector
    void parse_body_vector(statement& s)
    {
        s.names.push_back(expect_name("the body's name"));
        s.vector = parse_vector();
    }

    // assignments := assignment { ',' assignment }
    // assignment  := NAME [ '\'' ] '=' expr
    void parse_assignments(statement& s)
    {
        do {
            assignment a;
            a.target = expect_name("a name");
            a.velocity = accept(token_kind::prime);
            expect(token_kind::equals, "`=`");
            a.value = parse_expr();
            s.assignments.push_back(std::move(a));
        } while (accept(token_kind::comma));
    }

    // linearize := 'linearize' 'about' assignments
    void parse_linearize(statement& s)
    {
        expect_keyword("about");
        parse_assignments(s);
    }

    // independent := 'independent' NAME [ '\'' ] { ',' NAME [ '\'' ] }
    void parse_independent(statement& s)
    {
        do {
            assignment a;
            a.target = expect_name("a coordinate");
            a.velocity = accept(token_kind::prime);
            s.assignments.push_back(std::move(a));
        } while (accept(token_kind::comma));
    }

    // ratio := 'ratio' NAME '=' expr
    void parse_ratio(statement& s)
    {
        s.names.push_back(expect_name("the ratio's name"));
        expect(token_kind::equals, "`=`");
        s.value = parse_expr();
    }

    // limit := 'limit' NAME '->' ( '0' | 'oo' )
    void parse_limit(statement& s)
    {
        s.names.push_back(expect_name("the name of the ratio or parameter"));
        expect(token_kind::arrow, "`->`");
        const token& t = current();
        if ((t.kind == token_kind::integer && t.text == "0") || (t.kind == token_kind::name && t.text == "oo")) {
            s.limit_target = name_ref{t.text, t.where};
            take();
            return;
        }
        fail_here("`0` or `oo`");
    }

    // critical := 'critical' NAME 'from' expr 'to' expr
    void parse_critical(statement& s)
    {
        s.names.push_back(expect_name("the parameter that runs over the range"));
        expect_keyword("from");
        s.value = parse_expr();
        expect_keyword("to");
        s.right = parse_expr();
    }

    // rolls := 'rolls' NAME 'on' 'ground' { 'radius' expr | 'axis' NAME }
    void parse_rolls(statement& s)
    {
        s.names.push_back(expect_name("the name of the rolling body"));
        expect_keyword("on");
        if (!at_name("ground"))
            fail_here("`ground`, the plane the body rolls on");
        s.names.push_back({current().text, current().where});
        take();
        std::set<std::string> seen;
        while (at(token_kind::name)) {
            const token& option = current();
            if (!seen.insert(option.text).second)
                throw scene_error(option.where, quote(option.text) + " is given twice");
            if (accept_name("radius"))
                s.value = parse_expr();
            else if (accept_name("axis"))
                s.axis = expect_name("`x`, `y` or `z`");
            else
                fail_here("`radius`, `axis` or the end of the statement");
        }
    }

    // simulate := 'simulate' 'until' expr { 'step' expr | 'method' NAME | 'tolerance' expr }
    void parse_simulate(statement& s)
    {
        expect_keyword("until");
        s.value = parse_expr();
        std::set<std::string> seen;
        while (at(token_kind::name)) {
            const token& option = current();
            if (!seen.insert(option.text).second)
                throw scene_error(option.where, quote(option.text) + " is given twice");
            if (accept_name("step"))
                s.step = parse_expr();
            else if (accept_name("method"))
                s.method = expect_name("a method name");
            else if (accept_name("tolerance"))
                s.tolerance = parse_expr();
            else
                fail_here("`step`, `method`, `tolerance` or the end of the statement");
        }
    }

    // use := 'use' STRING
    void parse_use(statement& s) { s.text = expect(token_kind::string, "a file name in quotes").text; }

    // want := 'want' NAME { ',' NAME }
    void parse_want(statement& s)
    {
        do
            s.names.push_back(expect_name("a product such as `equations`"));
        while (accept(token_kind::comma));
    }

    // vector := '(' expr ',' expr [ ',' expr ] ')'
    vector_expr parse_vector()
    {
        vector_expr v;
        v.where = current().where;
        expect(token_kind::left_paren, "`(` to start a vector");
        v.components.push_back(parse_expr());
        while (accept(token_kind::comma)) {
            if (v.components.size() == 3)
                throw scene_error(tokens_[pos_ - 1].where, "a vector has 2 or 3 components");
            v.components.push_back(parse_expr());
        }
        if (v.components.size() < 2)
            fail_here("`,`: a vector has 2 or 3 components");
        expect(token_kind::right_paren, "`)` to close the vector");
        return v;
    }

    // ---- expressions ----------------------------------------------------------

    /// Guards recursion: every operand of a sign or power, and every parenthesis or
    /// call argument, passes through parse_unary, which counts one level.
    class depth_guard {
    public:
        depth_guard(parser& p, const source_location& where) : p_(p)
        {
            if (++p_.depth_ > max_expression_depth)
                throw scene_error(where, "expression nested more than " +
                                             std::to_string(max_expression_depth) + " levels deep");
        }
        ~depth_guard() { --p_.depth_; }
        depth_guard(const depth_guard&) = delete;
        depth_guard& operator=(const depth_guard&) = delete;

    private:
        parser& p_;
    };

    static expr_ptr make(expr_node::kind kind, const source_location& where, std::string text = {})
    {
        auto node = std::make_unique<expr_node>();
        node->node_kind = kind;
        node->where = where;
        node->text = std::move(text);
        return node;
    }

    // expr := term { ('+' | '-') term }
    expr_ptr parse_expr()
    {
        source_location where = current().where;
        expr_ptr first = parse_term();
        if (!at(token_kind::plus) && !at(token_kind::minus))
            return first;
        expr_ptr sum = make(expr_node::kind::sum, where);
        sum->operands.push_back(std::move(first));
        sum->ops.push_back('+');
        while (at(token_kind::plus) || at(token_kind::minus)) {
            sum->ops.push_back(take().text[0]);
            sum->operands.push_back(parse_term());
        }
        return sum;
    }

    // term := unary { ('*' | '/') unary }
    expr_ptr parse_term()
    {
        source_location where = current().where;
        expr_ptr first = parse_unary();
        if (!at(token_kind::star) && !at(token_kind::slash))
            return first;
        expr_ptr product = make(expr_node::kind::product, where);
        product->operands.push_back(std::move(first));
        product->ops.push_back('*');
        while (at(token_kind::star) || at(token_kind::slash)) {
            product->ops.push_back(take().text[0]);
            product->operands.push_back(parse_unary());
        }
        return product;
    }

    // unary := ('-' | '+') unary | power
    expr_ptr parse_unary()
    {
        depth_guard guard(*this, current().where);
        source_location where = current().where;
        if (accept(token_kind::minus)) {
            expr_ptr node = make(expr_node::kind::negate, where);
            node->operands.push_back(parse_unary());
            return node;
        }
        if (accept(token_kind::plus))
            return parse_unary();
        return parse_power();
    }

    // power := postfix [ '^' unary ]      (right-associative; -x^2 is -(x^2))
    expr_ptr parse_power()
    {
        expr_ptr base = parse_postfix();
        if (!at(token_kind::caret))
            return base;
        source_location where = current().where;
        take();
        expr_ptr node = make(expr_node::kind::power, where);
        node->operands.push_back(std::move(base));
        node->operands.push_back(parse_unary());
        return node;
    }

    // postfix := primary [ '\'' ]
    expr_ptr parse_postfix()
    {
        expr_ptr node = parse_primary();
        if (!at(token_kind::prime))
            return node;
        if (node->node_kind != expr_node::kind::name)
            throw scene_error(current().where, "`'` (a velocity) follows a coordinate's name only");
        take();
        node->node_kind = expr_node::kind::velocity;
        return node;
    }

    // primary := INTEGER | DECIMAL | WILDCARD | NAME [ '(' expr { ',' expr } ')' ] | '(' expr ')'
    expr_ptr parse_primary()
    {
        const token& t = current();
        switch (t.kind) {
        case token_kind::integer:
            take();
            return make(expr_node::kind::integer, t.where, t.text);
        case token_kind::decimal:
            take();
            return make(expr_node::kind::decimal, t.where, t.text);
        case token_kind::wildcard:
            take();
            return make(expr_node::kind::wildcard, t.where, t.text);
        case token_kind::name: {
            take();
            if (!at(token_kind::left_paren))
                return make(expr_node::kind::name, t.where, t.text);
            take();
            expr_ptr call = make(expr_node::kind::call, t.where, t.text);
            call->operands.push_back(parse_expr());
            while (accept(token_kind::comma))
                call->operands.push_back(parse_expr());
            expect(token_kind::right_paren, "`)` to close the call of `" + t.text + "`");
            return call;
        }
        case token_kind::left_paren: {
            take();
            expr_ptr inner = parse_expr();
            expect(token_kind::right_paren, "`)`");
            return inner;
        }
        default:
            fail_here("an expression");
        }
    }

    const std::vector<token>& tokens_;
    std::size_t pos_ = 0;
    int depth_ = 0;
};

} // namespace

scene_ast parse_scene(const std::vector<token>& tokens) { return parser(tokens).parse_scene(); }

std::vector<parsed_rule> parse_rules(const std::vector<token>& tokens) { return parser(tokens).parse_rules(); }

} // namespace lagrange
