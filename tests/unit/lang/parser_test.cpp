// The parser (spec §2): AST shapes, precedence, the line-start and modifier rules, error
// recovery, and node ranges.
#include <catch2/catch.hpp>

#include "interpreter.hpp"
#include "parser.hpp"

#include <algorithm>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace crt::lang;

namespace {

struct Parsed {
    std::unique_ptr<SourceFile> file;
    Arena arena;
    DiagnosticBag diagnostics;
    Script script;

    std::string text(SourceRange range) const {
        return std::string(file->text().substr(range.begin, range.end - range.begin));
    }
    std::string text(const Node* node) const { return text(node->range); }
    size_t errorCount() const { return diagnostics.errorCount(); }
};

std::unique_ptr<Parsed> parseText(const std::string& text) {
    auto p = std::make_unique<Parsed>();
    p->file = std::make_unique<SourceFile>("p.crt", text);
    p->script = parse(*p->file, 0, p->arena, p->diagnostics);
    return p;
}

/// Parses text that must have no diagnostics.
std::unique_ptr<Parsed> parseOk(const std::string& text) {
    auto p = parseText(text);
    INFO("script: " << text);
    if (!p->diagnostics.items().empty()) INFO("first: " << p->diagnostics.items()[0].message);
    REQUIRE(p->diagnostics.items().empty());
    return p;
}

template <typename T> const T* as(const Node* node, NodeKind kind) {
    REQUIRE(node != nullptr);
    REQUIRE(node->kind == kind);
    return static_cast<const T*>(node);
}

const BinaryExpr* binary(const Node* node, BinaryOp op) {
    auto* b = as<BinaryExpr>(node, NodeKind::Binary);
    CHECK(b->op == op);
    return b;
}

const VarExpr* var(const Node* node, std::string_view name) {
    auto* v = as<VarExpr>(node, NodeKind::Var);
    CHECK(v->name == name);
    return v;
}

/// The direct children of a node, in source order.
std::vector<const Node*> children(const Node* node) {
    std::vector<const Node*> out;
    forEachChild(const_cast<Node*>(node), [&](const Node* child) {
        if (child) out.push_back(child);
    });
    return out;
}

void walk(const Node* node, const std::function<void(const Node*)>& visit) {
    visit(node);
    for (const Node* child : children(node)) walk(child, visit);
}

/// Every node of the script, in pre-order.
std::vector<const Node*> allNodes(const Parsed& p) {
    std::vector<const Node*> out;
    for (const Node* item : p.script.items) walk(item, [&](const Node* n) { out.push_back(n); });
    return out;
}

/// The source texts of every node of `kind`, in pre-order.
std::vector<std::string> textsOf(const Parsed& p, NodeKind kind) {
    std::vector<std::string> out;
    for (const Node* n : allNodes(p)) {
        if (n->kind == kind) out.push_back(p.text(n));
    }
    return out;
}

} // namespace

TEST_CASE("parser: '*' binds tighter than '+'") {
    auto p = parseOk("1 + 2 * 3");
    REQUIRE(p->script.items.size() == 1);
    auto* add = binary(p->script.items[0], BinaryOp::Add);
    CHECK(as<IntLit>(add->left, NodeKind::IntLit)->value == 1);
    auto* mul = binary(add->right, BinaryOp::Mul);
    CHECK(as<IntLit>(mul->left, NodeKind::IntLit)->value == 2);
    CHECK(as<IntLit>(mul->right, NodeKind::IntLit)->value == 3);

    auto q = parseOk("1 * 2 + 3");
    auto* add2 = binary(q->script.items[0], BinaryOp::Add);
    binary(add2->left, BinaryOp::Mul);
}

TEST_CASE("parser: the precedence ladder") {
    // or < and < comparison < + - ^ < * / % < unary < postfix
    auto p = parseOk("a || b && c == d + e * -f(1)");
    auto* orNode = binary(p->script.items[0], BinaryOp::Or);
    var(orNode->left, "a");
    auto* andNode = binary(orNode->right, BinaryOp::And);
    var(andNode->left, "b");
    auto* eq = binary(andNode->right, BinaryOp::Equal);
    var(eq->left, "c");
    auto* add = binary(eq->right, BinaryOp::Add);
    var(add->left, "d");
    auto* mul = binary(add->right, BinaryOp::Mul);
    var(mul->left, "e");
    auto* neg = as<UnaryExpr>(mul->right, NodeKind::Unary);
    CHECK(neg->op == UnaryOp::Minus);
    as<CallExpr>(neg->operand, NodeKind::Call);
}

TEST_CASE("parser: binary operators are left-associative") {
    auto p = parseOk("a - b - c");
    auto* outer = binary(p->script.items[0], BinaryOp::Sub);
    var(outer->right, "c");
    auto* inner = binary(outer->left, BinaryOp::Sub);
    var(inner->left, "a");
    var(inner->right, "b");

    auto q = parseOk("a ^ b + c % d / e");
    auto* plus = binary(q->script.items[0], BinaryOp::Add);
    binary(plus->left, BinaryOp::Intersect);
    auto* div = binary(plus->right, BinaryOp::Div);
    binary(div->left, BinaryOp::Mod);

    auto r = parseOk("a < b <= c");
    auto* le = binary(r->script.items[0], BinaryOp::LessEqual);
    binary(le->left, BinaryOp::Less);
}

TEST_CASE("parser: assignment and '?:' are right-associative") {
    auto p = parseOk("a = b = 1");
    auto* outer = as<AssignExpr>(p->script.items[0], NodeKind::Assign);
    CHECK(outer->name == "a");
    CHECK(p->text(outer->nameRange) == "a");
    auto* inner = as<AssignExpr>(outer->value, NodeKind::Assign);
    CHECK(inner->name == "b");

    auto q = parseOk("x = a ? b : c ? d : e");
    auto* assign = as<AssignExpr>(q->script.items[0], NodeKind::Assign);
    auto* t = as<TernaryExpr>(assign->value, NodeKind::Ternary);
    var(t->condition, "a");
    var(t->then, "b");
    auto* t2 = as<TernaryExpr>(t->otherwise, NodeKind::Ternary);
    var(t2->condition, "c");
}

TEST_CASE("parser: only a variable can be assigned") {
    auto p = parseText("a ? b : c = d");
    CHECK(p->errorCount() == 1);
    auto q = parseText("f(1) = 2");
    CHECK(q->errorCount() == 1);
}

TEST_CASE("parser: a modifier list binds like a call") {
    auto p = parseOk("a + b <translate v>");
    auto* add = binary(p->script.items[0], BinaryOp::Add);
    var(add->left, "a");
    auto* mod = as<ModifyExpr>(add->right, NodeKind::Modify);
    var(mod->target, "b");
    REQUIRE(mod->modifiers.size() == 1);
    CHECK(mod->modifiers[0].op == ModifierOp::Translate);
    var(mod->modifiers[0].argument, "v");

    auto q = parseOk("(a + b) <translate v>");
    auto* mod2 = as<ModifyExpr>(q->script.items[0], NodeKind::Modify);
    binary(mod2->target, BinaryOp::Add);
}

TEST_CASE("parser: modifiers apply in order and chain") {
    auto p = parseOk("s <translate vec3(1, 0, 0), rotate r * 2, scale 0.5> <scale 2>");
    auto* outer = as<ModifyExpr>(p->script.items[0], NodeKind::Modify);
    REQUIRE(outer->modifiers.size() == 1);
    CHECK(outer->modifiers[0].op == ModifierOp::Scale);
    auto* inner = as<ModifyExpr>(outer->target, NodeKind::Modify);
    REQUIRE(inner->modifiers.size() == 3);
    CHECK(inner->modifiers[0].op == ModifierOp::Translate);
    CHECK(inner->modifiers[1].op == ModifierOp::Rotate);
    CHECK(inner->modifiers[2].op == ModifierOp::Scale);
    binary(inner->modifiers[1].argument, BinaryOp::Mul);
    CHECK(p->text(inner->modifiers[0].range) == "translate vec3(1, 0, 0)");
    CHECK(p->text(inner->modifiers[1].range) == "rotate r * 2");
    CHECK(p->text(inner->modifiers[2].range) == "scale 0.5");
}

TEST_CASE("parser: a modifier argument stops before '>'") {
    auto p = parseOk("s <scale (a > b ? 1 : 2)>");
    auto* mod = as<ModifyExpr>(p->script.items[0], NodeKind::Modify);
    as<TernaryExpr>(mod->modifiers[0].argument, NodeKind::Ternary);
    // '<' not followed by a modifier keyword is a comparison.
    auto q = parseOk("x = a < scales");
    auto* assign = as<AssignExpr>(q->script.items[0], NodeKind::Assign);
    binary(assign->value, BinaryOp::Less);
}

TEST_CASE("parser: a '(' first on its line begins a new statement") {
    auto p = parseOk("a\n(b)");
    REQUIRE(p->script.items.size() == 2);
    var(p->script.items[0], "a");
    var(p->script.items[1], "b");

    auto call = parseOk("a (b)");
    REQUIRE(call->script.items.size() == 1);
    auto* c = as<CallExpr>(call->script.items[0], NodeKind::Call);
    var(c->callee, "a");
    REQUIRE(c->args.size() == 1);

    auto list = parseOk("a = b\n[1, 2]");
    REQUIRE(list->script.items.size() == 2);
    as<AssignExpr>(list->script.items[0], NodeKind::Assign);
    as<ListExpr>(list->script.items[1], NodeKind::List);

    auto index = parseOk("a = b [1]");
    REQUIRE(index->script.items.size() == 1);
    auto* assign = as<AssignExpr>(index->script.items[0], NodeKind::Assign);
    as<IndexExpr>(assign->value, NodeKind::Index);

    auto comment = parseOk("a\n-- a comment line\n(b)");
    CHECK(comment->script.items.size() == 2);
}

TEST_CASE("parser: a line-start '(' after an operator continues the expression") {
    auto p = parseOk("fov = 75.0 /\n(d / 0.6)");
    REQUIRE(p->script.items.size() == 1);
    auto* assign = as<AssignExpr>(p->script.items[0], NodeKind::Assign);
    auto* div = binary(assign->value, BinaryOp::Div);
    binary(div->right, BinaryOp::Div);

    auto args = parseOk("f(1,\n(2))");
    REQUIRE(args->script.items.size() == 1);
    CHECK(as<CallExpr>(args->script.items[0], NodeKind::Call)->args.size() == 2);

    auto attr = parseOk("s = Sphere { radius ->\n(1 + 2) }");
    REQUIRE(attr->script.items.size() == 1);
}

TEST_CASE("parser: '+' or '-' on the next line continues the statement") {
    auto p = parseOk("a = b\n- c");
    REQUIRE(p->script.items.size() == 1);
    auto* assign = as<AssignExpr>(p->script.items[0], NodeKind::Assign);
    CHECK(assign->name == "a");
    auto* sub = binary(assign->value, BinaryOp::Sub);
    var(sub->left, "b");
    var(sub->right, "c");

    auto q = parseOk("a = b\n+ c\nd");
    REQUIRE(q->script.items.size() == 2);
    binary(as<AssignExpr>(q->script.items[0], NodeKind::Assign)->value, BinaryOp::Add);
    var(q->script.items[1], "d");

    // Anything else after a complete expression starts a new statement.
    auto r = parseOk("a = b\n!c\nd = 1");
    CHECK(r->script.items.size() == 3);
}

TEST_CASE("parser: statements written side by side") {
    auto p = parseOk("Scene { a (b) }");
    auto* scene = as<SceneStmt>(p->script.items[0], NodeKind::Scene);
    REQUIRE(scene->statements.size() == 1);
    as<CallExpr>(scene->statements[0], NodeKind::Call);

    auto q = parseOk("Scene { a b c }");
    CHECK(as<SceneStmt>(q->script.items[0], NodeKind::Scene)->statements.size() == 3);

    auto r = parseOk("x = 2--3");
    REQUIRE(r->script.items.size() == 1);
    auto* assign = as<AssignExpr>(r->script.items[0], NodeKind::Assign);
    CHECK(as<IntLit>(assign->value, NodeKind::IntLit)->value == 2);
}

TEST_CASE("parser: literals carry their values") {
    auto p = parseOk("[42, 1.5, .25, 1e3, 2.5E-1, true, false, \"a\\\"b\\\\c\\nd\\te\", \"\"]");
    auto* list = as<ListExpr>(p->script.items[0], NodeKind::List);
    REQUIRE(list->items.size() == 9);
    CHECK(as<IntLit>(list->items[0], NodeKind::IntLit)->value == 42);
    CHECK(as<FloatLit>(list->items[1], NodeKind::FloatLit)->value == 1.5);
    CHECK(as<FloatLit>(list->items[2], NodeKind::FloatLit)->value == 0.25);
    CHECK(as<FloatLit>(list->items[3], NodeKind::FloatLit)->value == 1000.0);
    CHECK(as<FloatLit>(list->items[4], NodeKind::FloatLit)->value == 0.25);
    CHECK(as<BoolLit>(list->items[5], NodeKind::BoolLit)->value);
    CHECK_FALSE(as<BoolLit>(list->items[6], NodeKind::BoolLit)->value);
    CHECK(as<StringLit>(list->items[7], NodeKind::StringLit)->value == "a\"b\\c\nd\te");
    CHECK(as<StringLit>(list->items[8], NodeKind::StringLit)->value.empty());
}

TEST_CASE("parser: an integer literal beyond 64 bits is an error") {
    CHECK(parseText("x = 9223372036854775807")->errorCount() == 0);
    CHECK(parseText("x = 9223372036854775808")->errorCount() == 1);
}

TEST_CASE("parser: objects, macros and statements") {
    auto p = parseOk("Settings { width -> 10 height -> 20 }\n"
                     "m = Macro (a, b) { a + b }\n"
                     "s = Sphere { center -> vec3(0, 0, 0) radius -> 1 }\n"
                     "include \"lib.crt\"\n"
                     "Scene {\n"
                     "  while (i < 3) { i = i + 1 }\n"
                     "  for k in range(3) { s }\n"
                     "  if (a) { s } else if (b) { s } else { s }\n"
                     "}\n");
    REQUIRE(p->script.items.size() == 5);
    auto* settings = as<SettingsStmt>(p->script.items[0], NodeKind::Settings);
    REQUIRE(settings->attributes.size() == 2);
    CHECK(settings->attributes[0].name == "width");
    CHECK(settings->attributes[1].name == "height");

    auto* macro = as<MacroExpr>(as<AssignExpr>(p->script.items[1], NodeKind::Assign)->value,
                                NodeKind::Macro);
    REQUIRE(macro->params.size() == 2);
    CHECK(macro->params[0].name == "a");
    CHECK(macro->params[1].name == "b");
    REQUIRE(macro->body->statements.size() == 1);

    auto* sphere = as<ObjectExpr>(as<AssignExpr>(p->script.items[2], NodeKind::Assign)->value,
                                  NodeKind::Object);
    CHECK(sphere->typeName == "Sphere");
    CHECK(sphere->type == ObjectType::Sphere);
    REQUIRE(sphere->attributes.size() == 2);
    CHECK(p->text(sphere->attributes[0].range) == "center -> vec3(0, 0, 0)");
    CHECK(p->text(sphere->attributes[0].nameRange) == "center");

    auto* include = as<IncludeStmt>(p->script.items[3], NodeKind::Include);
    CHECK(include->path->value == "lib.crt");

    auto* scene = as<SceneStmt>(p->script.items[4], NodeKind::Scene);
    REQUIRE(scene->statements.size() == 3);
    as<WhileStmt>(scene->statements[0], NodeKind::While);
    auto* loop = as<ForStmt>(scene->statements[1], NodeKind::For);
    CHECK(loop->variable == "k");
    auto* branch = as<IfStmt>(scene->statements[2], NodeKind::If);
    auto* elseIf = as<IfStmt>(branch->otherwise, NodeKind::If);
    as<Block>(elseIf->otherwise, NodeKind::Block);
}

TEST_CASE("parser: three independent syntax errors give three diagnostics") {
    auto p = parseText("a = (1 + 2\n"
                       "b = 2\n"
                       "c = [1, 2,, 3]\n"
                       "d = 3\n"
                       "e = Sphere { radius = 2 }\n"
                       "f = 4\n");
    CHECK(p->diagnostics.items().size() == 3);
    CHECK(p->errorCount() == 3);
    std::vector<std::string> assigned;
    for (const Node* item : p->script.items) {
        if (item->kind == NodeKind::Assign) {
            assigned.emplace_back(static_cast<const AssignExpr*>(item)->name);
        }
    }
    CHECK(std::find(assigned.begin(), assigned.end(), "b") != assigned.end());
    CHECK(std::find(assigned.begin(), assigned.end(), "d") != assigned.end());
    CHECK(std::find(assigned.begin(), assigned.end(), "f") != assigned.end());
    // Each error is at the offending token.
    REQUIRE(p->diagnostics.items().size() == 3);
    CHECK(p->text(p->diagnostics.items()[0].range) == "b");
    CHECK(p->text(p->diagnostics.items()[1].range) == ",");
    CHECK(p->text(p->diagnostics.items()[2].range) == "=");
}

TEST_CASE("parser: errors on consecutive lines are each reported") {
    // Each line is an independent mistake (spec §2: one diagnostic per mistake), even though
    // Bison on its own would stay silent until three tokens are shifted after a recovery.
    auto p = parseText("a = )\nb = )\nc = )\nd = 1\n");
    CHECK(p->errorCount() == 3);
    REQUIRE_FALSE(p->script.items.empty());
    auto* last = as<AssignExpr>(p->script.items.back(), NodeKind::Assign);
    CHECK(last->name == "d");
}

TEST_CASE("parser: an error inside a block does not lose what follows") {
    auto p = parseText("Scene {\n  a = )\n  s\n}\nx = 1\n");
    CHECK(p->errorCount() == 1);
    REQUIRE(p->script.items.size() >= 2);
    auto* scene = as<SceneStmt>(p->script.items[0], NodeKind::Scene);
    bool sawS = false;
    for (const Node* s : scene->statements) sawS |= s->kind == NodeKind::Var;
    CHECK(sawS);
    auto* x = as<AssignExpr>(p->script.items.back(), NodeKind::Assign);
    CHECK(x->name == "x");
}

TEST_CASE("parser: recovery skips whole blocks") {
    // The '{' block after the error is skipped as a unit, so its line-start statements do
    // not resume parsing in the middle of it.
    auto p = parseText("x = 1 2 ) {\n  y = 2\n}\nz = 3\n");
    CHECK(p->errorCount() == 1);
    auto* z = as<AssignExpr>(p->script.items.back(), NodeKind::Assign);
    CHECK(z->name == "z");
}

TEST_CASE("parser: a missing '->' gets a fix-it") {
    auto p = parseText("s = Sphere { radius = 1 }");
    REQUIRE(p->errorCount() == 1);
    const Diagnostic& d = p->diagnostics.items()[0];
    REQUIRE(d.fixits.size() == 1);
    CHECK(d.fixits[0].replacement == "->");
    CHECK(p->text(d.fixits[0].range) == "=");
}

TEST_CASE("parser: unexpected end of file is reported at the end") {
    auto p = parseText("x = (1 +");
    REQUIRE(p->errorCount() == 1);
    CHECK(p->diagnostics.items()[0].range.begin == 8);
}

TEST_CASE("parser: a script with syntax errors is not evaluated") {
    EvalOptions options;
    std::ostringstream out;
    options.printOut = &out;
    Compilation c = compile("p.crt", "print(1)\nx = )\n", options);
    CHECK(c.diagnostics.hasErrors());
    CHECK(out.str().empty());
    CHECK_FALSE(c.scene.has_value());
}

/// A valid script with one of every kind of node.
constexpr const char* kEveryConstruct = "include \"lib.crt\"\n"
                                        "Settings { width -> 10 * 2 }\n"
                                        "sq = Macro (a, b) { a * b }\n"
                                        "s = Sphere { center -> vec3(0, 0, 0) radius -> -r }\n"
                                        "l = [1, 2.5, \"s\", true][0]\n"
                                        "c = a ? b : d\n"
                                        "Scene {\n"
                                        "  while (i < 3) { i = i + 1 }\n"
                                        "  for k in range(3) { s <translate vec3(k, 0, 0), scale 2> }\n"
                                        "  if (!false) { s } else if (x) { s } else { s }\n"
                                        "}\n";

TEST_CASE("parser: every node's range lies inside the file and its parent's range") {
    auto p = parseOk(kEveryConstruct);
    std::function<void(const Node*)> check = [&](const Node* node) {
        INFO("node: " << p->text(node));
        CHECK(node->range.file == 0);
        CHECK(node->range.begin <= node->range.end);
        CHECK(node->range.end <= p->file->size());
        CHECK(node->range.begin < node->range.end); // no empty node in a valid script
        for (const Node* child : children(node)) {
            INFO("child: " << p->text(child));
            CHECK(child->range.begin >= node->range.begin);
            CHECK(child->range.end <= node->range.end);
            check(child);
        }
    };
    for (const Node* item : p->script.items) check(item);
}

TEST_CASE("parser: every node's range covers exactly its source text") {
    auto p = parseOk(kEveryConstruct);
    CHECK(textsOf(*p, NodeKind::Include) == std::vector<std::string>{"include \"lib.crt\""});
    CHECK(textsOf(*p, NodeKind::Settings) ==
          std::vector<std::string>{"Settings { width -> 10 * 2 }"});
    CHECK(textsOf(*p, NodeKind::Macro) == std::vector<std::string>{"Macro (a, b) { a * b }"});
    CHECK(textsOf(*p, NodeKind::Object) ==
          std::vector<std::string>{"Sphere { center -> vec3(0, 0, 0) radius -> -r }"});
    CHECK(textsOf(*p, NodeKind::Unary) == std::vector<std::string>{"-r", "!false"});
    CHECK(textsOf(*p, NodeKind::Index) == std::vector<std::string>{"[1, 2.5, \"s\", true][0]"});
    CHECK(textsOf(*p, NodeKind::List) == std::vector<std::string>{"[1, 2.5, \"s\", true]"});
    CHECK(textsOf(*p, NodeKind::FloatLit) == std::vector<std::string>{"2.5"});
    CHECK(textsOf(*p, NodeKind::StringLit) == std::vector<std::string>{"\"lib.crt\"", "\"s\""});
    CHECK(textsOf(*p, NodeKind::BoolLit) == std::vector<std::string>{"true", "false"});
    CHECK(textsOf(*p, NodeKind::Ternary) == std::vector<std::string>{"a ? b : d"});
    CHECK(textsOf(*p, NodeKind::While) == std::vector<std::string>{"while (i < 3) { i = i + 1 }"});
    CHECK(textsOf(*p, NodeKind::For) ==
          std::vector<std::string>{"for k in range(3) { s <translate vec3(k, 0, 0), scale 2> }"});
    CHECK(textsOf(*p, NodeKind::Modify) ==
          std::vector<std::string>{"s <translate vec3(k, 0, 0), scale 2>"});
    CHECK(textsOf(*p, NodeKind::If) ==
          std::vector<std::string>{"if (!false) { s } else if (x) { s } else { s }",
                                   "if (x) { s } else { s }"});
    CHECK(textsOf(*p, NodeKind::Call) ==
          std::vector<std::string>{"vec3(0, 0, 0)", "range(3)", "vec3(k, 0, 0)"});
    CHECK(textsOf(*p, NodeKind::Binary) ==
          std::vector<std::string>{"10 * 2", "a * b", "i < 3", "i + 1"});
    CHECK(textsOf(*p, NodeKind::Assign) ==
          std::vector<std::string>{"sq = Macro (a, b) { a * b }",
                                   "s = Sphere { center -> vec3(0, 0, 0) radius -> -r }",
                                   "l = [1, 2.5, \"s\", true][0]", "c = a ? b : d", "i = i + 1"});
    std::vector<std::string> scenes = textsOf(*p, NodeKind::Scene);
    REQUIRE(scenes.size() == 1);
    CHECK(scenes[0].substr(0, 7) == "Scene {");
    CHECK(scenes[0].back() == '}');
    std::vector<std::string> blocks = textsOf(*p, NodeKind::Block);
    REQUIRE(!blocks.empty());
    CHECK(blocks[0] == "{ a * b }");
    for (const std::string& b : blocks) {
        CHECK(b.front() == '{');
        CHECK(b.back() == '}');
    }
}

TEST_CASE("parser: a binary node's range covers parenthesised operands") {
    // The range of '(a + b) * c' includes the parentheses, not just "a + b) * c".
    auto p = parseOk("x = (a + b) * c\ny = a * (b + c)\nz = (a) + (b)");
    CHECK(textsOf(*p, NodeKind::Binary) ==
          std::vector<std::string>{"(a + b) * c", "a + b", "a * (b + c)", "b + c", "(a) + (b)"});
}

TEST_CASE("parser: ranges of parenthesised expressions used elsewhere") {
    auto p = parseOk("x = -(a)\ny = (f)(1)\nz = [(1)]");
    CHECK(textsOf(*p, NodeKind::Unary) == std::vector<std::string>{"-(a)"});
    CHECK(textsOf(*p, NodeKind::Call) == std::vector<std::string>{"(f)(1)"});
    CHECK(textsOf(*p, NodeKind::List) == std::vector<std::string>{"[(1)]"});
}
