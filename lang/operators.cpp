// Expression evaluation: arithmetic, comparison, logic, indexing, lists and CSG (spec §3).
#include "interpreter_impl.hpp"

#include "builtins.hpp"

#include <glm/matrix.hpp>

#include <cmath>
#include <limits>

namespace crt::lang {

std::string_view kindName(ValueKind kind) {
    switch (kind) {
    case ValueKind::Unset: return "unset";
    case ValueKind::Poisoned: return "error";
    case ValueKind::None: return "none";
    case ValueKind::Int: return "int";
    case ValueKind::Float: return "float";
    case ValueKind::Bool: return "bool";
    case ValueKind::String: return "string";
    case ValueKind::Vec3: return "vec3";
    case ValueKind::Color: return "colour";
    case ValueKind::List: return "list";
    case ValueKind::Entity: return "entity";
    case ValueKind::Material: return "material";
    case ValueKind::Light: return "light";
    case ValueKind::Camera: return "camera";
    case ValueKind::Background: return "background";
    case ValueKind::Fog: return "fog";
    case ValueKind::Medium: return "medium";
    case ValueKind::Texture: return "texture";
    case ValueKind::BlobComponent: return "blob component";
    case ValueKind::Spline: return "spline";
    case ValueKind::Function: return "Function";
    case ValueKind::Macro: return "macro";
    case ValueKind::Builtin: return "function";
    case ValueKind::Modifiers: return "modifiers";
    }
    return "value";
}

std::string typeName(const Value& value) {
    if (value.isObject() && value.objectType != ObjectType::Count) {
        return std::string(objectInfo(value.objectType).name);
    }
    return std::string(kindName(value.kind));
}

std::string operandError(std::string_view op, const Value& left, const Value& right) {
    std::string message =
        fmt::format("cannot apply '{}' to {} and {}", op, typeName(left), typeName(right));
    if (op == "^" && left.isNumber() && right.isNumber())
        message += "; '^' is the intersection of solids: write pow(a, b) for a power";
    return message;
}

namespace {

bool isVector(const Value& v) { return v.kind == ValueKind::Vec3 || v.kind == ValueKind::Color; }

/// Component-wise a (op) b on vec3 or color. For two colors, '*' and '/' combine the
/// alphas too and '+' and '-' keep the smaller one, so every operation treats its operands
/// alike; a color and a number keep the color's alpha (scaling does not fade it).
Value componentWise(const Value& a, const Value& b, char op) {
    Value r = a.kind == ValueKind::Vec3 || a.kind == ValueKind::Color ? a : b;
    int components = 3;
    if (a.kind == ValueKind::Color && b.kind == ValueKind::Color) {
        if (op == '+' || op == '-') r.v[3] = std::min(a.v[3], b.v[3]);
        else components = 4;
    }
    for (int k = 0; k < components; ++k) {
        double x = isVector(a) ? a.v[k] : a.asDouble();
        double y = isVector(b) ? b.v[k] : b.asDouble();
        switch (op) {
        case '+': r.v[k] = x + y; break;
        case '-': r.v[k] = x - y; break;
        case '*': r.v[k] = x * y; break;
        default: r.v[k] = x / y; break;
        }
    }
    return r;
}

bool checkedInt(BinaryOp op, int64_t a, int64_t b, int64_t& out) {
    switch (op) {
    case BinaryOp::Add: return !__builtin_add_overflow(a, b, &out);
    case BinaryOp::Sub: return !__builtin_sub_overflow(a, b, &out);
    case BinaryOp::Mul: return !__builtin_mul_overflow(a, b, &out);
    default: return false;
    }
}

} // namespace

std::partial_ordering compareNumbers(const Value& a, const Value& b) {
    if (a.kind == ValueKind::Int && b.kind == ValueKind::Int) return a.i <=> b.i;
    if (a.kind == ValueKind::Float && b.kind == ValueKind::Float) return a.f <=> b.f;
    // An int against a float, without rounding the int to a double.
    bool flipped = a.kind == ValueKind::Float;
    int64_t i = flipped ? b.i : a.i;
    double f = flipped ? a.f : b.f;
    std::partial_ordering order = std::partial_ordering::unordered;
    if (std::isnan(f)) return order;
    if (f >= 9223372036854775808.0) {
        order = std::partial_ordering::less;
    } else if (f < -9223372036854775808.0) {
        order = std::partial_ordering::greater;
    } else {
        double whole = std::floor(f);
        auto w = static_cast<int64_t>(whole);
        order = i != w ? (i <=> w) : (whole == f ? std::partial_ordering::equivalent : std::partial_ordering::less);
    }
    if (!flipped) return order;
    return order == std::partial_ordering::less ? std::partial_ordering::greater
           : order == std::partial_ordering::greater ? std::partial_ordering::less
                                                     : order;
}

namespace {

/// Equality of two values that are not both lists (lists are compared by valuesEqual).
bool scalarsEqual(const Value& a, const Value& b) {
    if (a.isNumber() && b.isNumber()) return compareNumbers(a, b) == 0;
    switch (a.kind) {
    case ValueKind::None: return true;
    case ValueKind::Bool: return a.b == b.b;
    case ValueKind::String: return *a.s == *b.s;
    case ValueKind::Vec3: return a.v[0] == b.v[0] && a.v[1] == b.v[1] && a.v[2] == b.v[2];
    case ValueKind::Color:
        return a.v[0] == b.v[0] && a.v[1] == b.v[1] && a.v[2] == b.v[2] && a.v[3] == b.v[3];
    case ValueKind::Macro: return a.closure == b.closure;
    case ValueKind::Modifiers: return a.modifiers == b.modifiers;
    default: return a.index == b.index && a.objectType == b.objectType; // objects: identity
    }
}

} // namespace

bool valuesEqual(const Value& a, const Value& b) {
    // Without recursion: lists can nest as deep as a loop makes them.
    std::vector<std::pair<const Value*, const Value*>> pending{{&a, &b}};
    while (!pending.empty()) {
        auto [x, y] = pending.back();
        pending.pop_back();
        if (x->kind != ValueKind::List) {
            if (!scalarsEqual(*x, *y)) return false;
            continue;
        }
        if (x->list == y->list) continue; // the same list
        if (x->list->size() != y->list->size()) return false;
        for (size_t i = x->list->size(); i-- > 0;) { // reversed: compared in order
            const Value& u = (*x->list)[i];
            const Value& v = (*y->list)[i];
            if (u.kind != v.kind && !(u.isNumber() && v.isNumber())) return false;
            pending.emplace_back(&u, &v);
        }
    }
    return true;
}

// Kept to a bare dispatch so that every case is a tail call: the interpreter's time goes
// into this function's prologue otherwise.
Value Interpreter::eval(const Expr* node) {
    NestingLevel level(*this, node);
    switch (node->kind) {
    case NodeKind::IntLit: return Value::integer(static_cast<const IntLit*>(node)->value);
    case NodeKind::FloatLit: return Value::number(static_cast<const FloatLit*>(node)->value);
    case NodeKind::BoolLit: return Value::boolean(static_cast<const BoolLit*>(node)->value);
    case NodeKind::StringLit: return evalString(static_cast<const StringLit*>(node));
    case NodeKind::Var: return evalVar(static_cast<const VarExpr*>(node));
    case NodeKind::Assign: return assign(static_cast<const AssignExpr*>(node));
    case NodeKind::Unary: return evalUnary(static_cast<const UnaryExpr*>(node));
    case NodeKind::Binary: return evalBinary(static_cast<const BinaryExpr*>(node));
    case NodeKind::Ternary: return evalTernary(static_cast<const TernaryExpr*>(node));
    case NodeKind::Call: return evalCall(static_cast<const CallExpr*>(node));
    case NodeKind::Index: return evalIndex(static_cast<const IndexExpr*>(node));
    case NodeKind::Component: return evalComponent(static_cast<const ComponentExpr*>(node));
    case NodeKind::Modify: return evalModify(static_cast<const ModifyExpr*>(node));
    case NodeKind::ModifierList:
        return evalModifierList(static_cast<const ModifierListExpr*>(node));
    case NodeKind::List: return evalList(static_cast<const ListExpr*>(node));
    case NodeKind::Object: return evalObject(static_cast<const ObjectExpr*>(node));
    case NodeKind::Macro: return evalMacro(static_cast<const MacroExpr*>(node));
    case NodeKind::Function: return evalFunction(static_cast<const FunctionExpr*>(node));
    default: return notAnExpression(node);
    }
}

Value Interpreter::notAnExpression(const Expr* node) { fail(node->range, "this is not an expression"); }

Value Interpreter::evalString(const StringLit* node) {
    return Value::string(newString(std::string(node->value)));
}

Value Interpreter::evalTernary(const TernaryExpr* node) {
    return eval(condition(node->condition, "?:") ? node->then : node->otherwise);
}

Value Interpreter::evalUnary(const UnaryExpr* node) {
    Value v = eval(node->operand);
    switch (node->op) {
    case UnaryOp::Not:
        if (v.kind == ValueKind::Bool) return Value::boolean(!v.b);
        break;
    case UnaryOp::Plus:
        if (v.isNumber() || isVector(v)) return v;
        break;
    case UnaryOp::Minus:
        if (v.kind == ValueKind::Int) {
            if (v.i == std::numeric_limits<int64_t>::min()) fail(node->range, "integer overflow in '-'");
            return Value::integer(-v.i);
        }
        if (v.kind == ValueKind::Float) return Value::number(-v.f);
        if (isVector(v)) {
            for (int k = 0; k < 3; ++k) v.v[k] = -v.v[k];
            return v;
        }
        break;
    }
    fail(node->opRange, fmt::format("cannot apply '{}' to {}", opSpelling(node->op), typeName(v)));
}

Value Interpreter::evalLogical(const BinaryExpr* node) {
    BinaryOp op = node->op;
    Value left = eval(node->left);
    if (left.kind != ValueKind::Bool) {
        fail(node->left->range, fmt::format("the operands of '{}' must be bools, not {}",
                                            opSpelling(op), typeName(left)));
    }
    if (left.b == (op == BinaryOp::Or)) return left; // short-circuit
    Value right = eval(node->right);
    if (right.kind != ValueKind::Bool) {
        fail(node->right->range, fmt::format("the operands of '{}' must be bools, not {}",
                                             opSpelling(op), typeName(right)));
    }
    return right;
}

Value Interpreter::evalBinary(const BinaryExpr* node) {
    BinaryOp op = node->op;
    if (op == BinaryOp::And || op == BinaryOp::Or) return evalLogical(node);
    Value a = eval(node->left);
    Value b = eval(node->right);
    // The hot paths of loops: numbers. Everything else, errors included, is out of line.
    if (a.kind == ValueKind::Int && b.kind == ValueKind::Int) {
        int64_t result;
        switch (op) {
        case BinaryOp::Add:
            if (__builtin_add_overflow(a.i, b.i, &result)) break;
            return Value::integer(result);
        case BinaryOp::Sub:
            if (__builtin_sub_overflow(a.i, b.i, &result)) break;
            return Value::integer(result);
        case BinaryOp::Less: return Value::boolean(a.i < b.i);
        case BinaryOp::Greater: return Value::boolean(a.i > b.i);
        case BinaryOp::LessEqual: return Value::boolean(a.i <= b.i);
        case BinaryOp::GreaterEqual: return Value::boolean(a.i >= b.i);
        default: break;
        }
    } else if (a.isNumber() && b.isNumber()) {
        double x = a.asDouble(), y = b.asDouble();
        switch (op) {
        case BinaryOp::Add: return Value::number(x + y);
        case BinaryOp::Sub: return Value::number(x - y);
        case BinaryOp::Mul: return Value::number(x * y);
        case BinaryOp::Div:
            if (y != 0) return Value::number(x / y);
            break; // warned about below
        default: break;
        }
    }
    return binaryOnValues(node, a, b);
}

Value Interpreter::binaryOnValues(const BinaryExpr* node, const Value& a, const Value& b) {
    // Numbers: everything evalBinary did not settle inline, with exact checks and errors.
    if (a.kind == ValueKind::Int && b.kind == ValueKind::Int) return binaryOnInts(node, a, b);
    if (a.isNumber() && b.isNumber()) return binaryOnNumbers(node, a, b);
    return binaryOnNonNumbers(node, a, b);
}

Value Interpreter::binaryOnInts(const BinaryExpr* node, const Value& a, const Value& b) {
    BinaryOp op = node->op;
    int64_t result = 0;
    switch (op) {
    case BinaryOp::Add:
    case BinaryOp::Sub:
    case BinaryOp::Mul:
        if (!checkedInt(op, a.i, b.i, result)) {
            fail(node->opRange, fmt::format("integer overflow in '{}'", opSpelling(op)));
        }
        return Value::integer(result);
    case BinaryOp::Div:
    case BinaryOp::Mod:
        if (b.i == 0) {
            fail(node->opRange, op == BinaryOp::Div ? "integer division by zero"
                                                    : "integer modulo by zero");
        }
        if (b.i == -1) {
            // x / -1 overflows for the smallest int; x % -1 is always 0.
            if (op == BinaryOp::Mod) return Value::integer(0);
            if (a.i == std::numeric_limits<int64_t>::min()) {
                fail(node->opRange, "integer overflow in '/'");
            }
        }
        return Value::integer(op == BinaryOp::Div ? a.i / b.i : a.i % b.i);
    case BinaryOp::Less: return Value::boolean(a.i < b.i);
    case BinaryOp::Greater: return Value::boolean(a.i > b.i);
    case BinaryOp::LessEqual: return Value::boolean(a.i <= b.i);
    case BinaryOp::GreaterEqual: return Value::boolean(a.i >= b.i);
    case BinaryOp::Equal: return Value::boolean(a.i == b.i);
    case BinaryOp::NotEqual: return Value::boolean(a.i != b.i);
    default: break;
    }
    fail(node->opRange, operandError(opSpelling(op), a, b));
}

void Interpreter::warnDivisionByZero(const BinaryExpr* node, double dividend) {
    // Once per '/' of the script: a loop would repeat it for nothing.
    const SourceRange& where = node->opRange;
    if (!divisionsWarned_.insert((uint64_t{where.file} << 32) | where.begin).second) return;
    diagnostics_.warning(WarningKind::DivisionByZero, where,
                         fmt::format("float division by zero gives {}", std::isnan(dividend) || dividend == 0 ? "nan"
                                                                    : dividend > 0                             ? "inf"
                                                                                                               : "-inf"));
}

/// Two numbers, at least one a float.
Value Interpreter::binaryOnNumbers(const BinaryExpr* node, const Value& a, const Value& b) {
    BinaryOp op = node->op;
    double x = a.asDouble(), y = b.asDouble();
    // Comparisons are exact: 2^53 + 1 is not equal to the float 2^53.
    std::partial_ordering order = compareNumbers(a, b);
    switch (op) {
    case BinaryOp::Add: return Value::number(x + y);
    case BinaryOp::Sub: return Value::number(x - y);
    case BinaryOp::Mul: return Value::number(x * y);
    case BinaryOp::Div:
        if (y == 0) warnDivisionByZero(node, x);
        return Value::number(x / y);
    case BinaryOp::Mod: return Value::number(std::fmod(x, y));
    case BinaryOp::Less: return Value::boolean(order < 0);
    case BinaryOp::Greater: return Value::boolean(order > 0);
    case BinaryOp::LessEqual: return Value::boolean(order <= 0);
    case BinaryOp::GreaterEqual: return Value::boolean(order >= 0);
    case BinaryOp::Equal: return Value::boolean(order == 0);
    case BinaryOp::NotEqual: return Value::boolean(order != 0);
    default: break;
    }
    fail(node->opRange, operandError(opSpelling(op), a, b));
}

/// Equality of any two values of one type, joining strings and lists, CSG and vector arithmetic.
Value Interpreter::binaryOnNonNumbers(const BinaryExpr* node, const Value& a, const Value& b) {
    BinaryOp op = node->op;
    if (a.kind == ValueKind::None || b.kind == ValueKind::None) {
        fail(node->opRange, operandError(opSpelling(op), a, b));
    }
    switch (op) {
    case BinaryOp::Equal:
    case BinaryOp::NotEqual:
        if (a.kind != b.kind) {
            fail(node->opRange, fmt::format("cannot compare {} and {} with '{}'", typeName(a),
                                            typeName(b), opSpelling(op)));
        }
        return Value::boolean(valuesEqual(a, b) == (op == BinaryOp::Equal));
    case BinaryOp::Add:
        if (a.kind == ValueKind::String || b.kind == ValueKind::String) {
            bool printable = [](const Value& v) {
                return v.kind == ValueKind::String || v.isNumber() || v.kind == ValueKind::Bool;
            }(a.kind == ValueKind::String ? b : a);
            if (printable) return concatenate(a, b);
        }
        if (a.kind == ValueKind::List && b.kind == ValueKind::List)
            return joinLists(*a.list, *b.list, node);
        [[fallthrough]];
    case BinaryOp::Sub:
        if (a.kind == ValueKind::Entity && b.kind == ValueKind::Entity) return csg(op, a, b, node);
        if (isVector(a) && a.kind == b.kind) {
            return componentWise(a, b, op == BinaryOp::Add ? '+' : '-');
        }
        break;
    case BinaryOp::Intersect:
        if (a.kind == ValueKind::Entity && b.kind == ValueKind::Entity) return csg(op, a, b, node);
        break;
    case BinaryOp::Mul:
        if (isVector(a) && (b.isNumber() || b.kind == a.kind)) return componentWise(a, b, '*');
        if (isVector(b) && a.isNumber()) return componentWise(a, b, '*');
        break;
    case BinaryOp::Div:
        if (isVector(a) && b.isNumber()) return componentWise(a, b, '/');
        if (isVector(a) && b.kind == a.kind) return componentWise(a, b, '/');
        break;
    default: break;
    }
    fail(node->opRange, operandError(opSpelling(op), a, b));
}

Value Interpreter::concatenate(const Value& a, const Value& b) {
    // Sized and checked before anything is copied: a loop doubling a string reaches the
    // memory limit with an error, not with an allocation the system refuses.
    constexpr size_t kScalarText = 32; // the longest text of a number or bool, with room
    auto textSize = [](const Value& v) { return v.kind == ValueKind::String ? v.s->size() : kScalarText; };
    checkRoom(textSize(a) + textSize(b));
    std::string text;
    text.reserve(textSize(a) + textSize(b));
    text += a.kind == ValueKind::String ? *a.s : str(a);
    text += b.kind == ValueKind::String ? *b.s : str(b);
    return Value::string(newString(std::move(text)));
}

Value Interpreter::joinLists(const std::vector<Value>& a, const std::vector<Value>& b,
                             const BinaryExpr* node) {
    const size_t length = a.size() + b.size();
    if (length > options_.limits.maxEntities) {
        fail(node->opRange,
             fmt::format("joining makes a list longer than {} items; raise the limit with "
                         "--max-entities",
                         options_.limits.maxEntities));
    }
    checkRoom(length * sizeof(Value)); // before the copy, as for strings
    std::vector<Value> items;
    items.reserve(length);
    items.insert(items.end(), a.begin(), a.end());
    items.insert(items.end(), b.begin(), b.end());
    return Value::listOf(newList(std::move(items)));
}

Value Interpreter::evalIndex(const IndexExpr* node) {
    Value object = eval(node->object);
    Value index = eval(node->index);
    if (object.kind != ValueKind::List) {
        fail(node->object->range, fmt::format("cannot index {}; only lists can be indexed", typeName(object)));
    }
    if (index.kind != ValueKind::Int) {
        Diagnostic& d = diagnostics_.error(node->index->range,
                                           fmt::format("a list index must be an int, not {}", typeName(index)));
        addIntFixIt(d, index, node->index->range);
        throw EvalError{};
    }
    int64_t length = static_cast<int64_t>(object.list->size());
    if (index.i < 0 || index.i >= length) {
        fail(node->index->range, fmt::format("index {} is out of range for a list of length {}",
                                             index.i, length));
    }
    return (*object.list)[static_cast<size_t>(index.i)];
}

Value Interpreter::evalComponent(const ComponentExpr* node) {
    Value object = eval(node->object);
    const std::string_view names = object.kind == ValueKind::Vec3    ? "xyz"
                                   : object.kind == ValueKind::Color ? "rgba"
                                                                     : "";
    if (names.empty()) {
        fail(node->object->range,
             fmt::format("cannot read the component '{}' of {}; only a vec3 (x, y, z) "
                         "and a colour (r, g, b, a) have components",
                         node->name, typeName(object)));
    }
    const size_t index =
        node->name.size() == 1 ? names.find(node->name[0]) : std::string_view::npos;
    if (index == std::string_view::npos) {
        fail(node->nameRange,
             fmt::format("{} has no component '{}'; its components are {}", typeName(object),
                         node->name,
                         object.kind == ValueKind::Vec3 ? "x, y and z" : "r, g, b and a"));
    }
    return Value::number(object.v[index]);
}

Value Interpreter::evalList(const ListExpr* node) {
    if (node->items.size() > options_.limits.maxEntities) {
        fail(node->range, fmt::format("a list longer than {} items; raise the limit with --max-entities",
                                      options_.limits.maxEntities));
    }
    std::vector<Value> items;
    items.reserve(node->items.size());
    for (const Expr* item : node->items) {
        Value v = eval(item);
        if (v.kind == ValueKind::None) fail(item->range, "a list item has no value (none)");
        items.push_back(v);
    }
    return Value::listOf(newList(std::move(items)));
}

Value Interpreter::csg(BinaryOp op, const Value& left, const Value& right, const BinaryExpr* node) {
    for (const Value* operand : {&left, &right}) {
        if (!scene_.entities[operand->index].solid) {
            const Expr* where = operand == &left ? node->left : node->right;
            if (operand->objectType == ObjectType::Lathe) {
                fail(where->range,
                     fmt::format("this Lathe's curve does not close, so it is a surface and "
                                 "cannot be used in CSG ('{}'): end it where it starts, or start "
                                 "and end it on the y axis",
                                 opSpelling(op)));
            }
            if (std::string open = openMeshReason(operand->index); !open.empty()) {
                fail(where->range, fmt::format("this Mesh is not closed, so it is a surface and "
                                               "cannot be used in CSG ('{}'): {}",
                                               opSpelling(op), open));
            }
            if (operand->objectType == ObjectType::Isosurface) {
                fail(where->range, fmt::format("this Isosurface is open, so it is a surface and cannot "
                                               "be used in CSG ('{}'): leave out 'open'",
                                               opSpelling(op)));
            }
            fail(where->range, fmt::format("{} is not a solid, so it cannot be used in CSG ('{}'); "
                                           "solids are {}",
                                           typeName(*operand), opSpelling(op), solidTypeList()));
        }
    }
    scene::CsgNode csg;
    csg.op = op == BinaryOp::Add   ? scene::CsgOp::Union
             : op == BinaryOp::Sub ? scene::CsgOp::Difference
                                   : scene::CsgOp::Intersection;
    csg.left = static_cast<int32_t>(left.index);
    csg.right = static_cast<int32_t>(right.index);
    int32_t index = addEntity(scene::EntityDesc{csg, -1, true, span(node->range)},
                              EntityInfo{node->range, ObjectType::Count, false});
    return Value::object(ValueKind::Entity, ObjectType::Count, static_cast<uint32_t>(index));
}

scene::Modifier Interpreter::evalMove(const Modifier& m) {
    Value arg = eval(m.argument);
    scene::Modifier mod;
    mod.kind = m.op == ModifierOp::Translate ? scene::ModifierKind::Translate
               : m.op == ModifierOp::Rotate  ? scene::ModifierKind::Rotate
                                             : scene::ModifierKind::Scale;
    if (arg.kind == ValueKind::Vec3) {
        mod.value = {arg.v[0], arg.v[1], arg.v[2]};
    } else if (m.op == ModifierOp::Scale && arg.isNumber()) {
        mod.value = glm::dvec3(arg.asDouble());
    } else {
        fail(m.argument->range,
             fmt::format("'{}' takes a {}, not {}", opSpelling(m.op),
                         m.op == ModifierOp::Scale ? "number or a vec3" : "vec3", typeName(arg)));
    }
    for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(mod.value[k])) {
            fail(m.argument->range,
                 fmt::format("'{}' has a component that is not finite", opSpelling(m.op)));
        }
        if (m.op == ModifierOp::Scale && mod.value[k] == 0.0) {
            fail(m.argument->range, "'scale' by zero flattens the object; use a non-zero scale");
        }
    }
    return mod;
}

scene::Modifier Interpreter::evalMatrix(const Modifier& m) {
    Value arg = eval(m.argument);
    constexpr std::string_view kShape =
        "'matrix' takes a list of 12 numbers: where x, y and z go, then the offset";
    if (arg.kind != ValueKind::List)
        fail(m.argument->range, fmt::format("{}, not {}", kShape, typeName(arg)));
    if (arg.list->size() != 12)
        fail(m.argument->range, fmt::format("{}; this list has {}", kShape, arg.list->size()));
    double numbers[12];
    for (size_t k = 0; k < 12; ++k) {
        const Value& item = (*arg.list)[k];
        if (!item.isNumber())
            fail(m.argument->range, fmt::format("{}; item {} is {}", kShape, k, typeName(item)));
        numbers[k] = item.asDouble();
        if (!std::isfinite(numbers[k]))
            fail(m.argument->range, fmt::format("'matrix' item {} is not finite", k));
    }
    scene::Modifier mod;
    mod.kind = scene::ModifierKind::Matrix;
    for (int column = 0; column < 3; ++column)
        mod.linear[column] =
            glm::dvec3(numbers[3 * column], numbers[3 * column + 1], numbers[3 * column + 2]);
    mod.value = glm::dvec3(numbers[9], numbers[10], numbers[11]);
    const double determinant = glm::determinant(mod.linear);
    if (!std::isnormal(determinant))
        fail(m.argument->range,
             "this 'matrix' flattens the object (its first nine numbers have no inverse)");
    return mod;
}

namespace {

/// What `<shadow false>`, `<camera false>` or `<reflected false>` hides an entity from.
uint8_t hiddenBit(ModifierOp op) {
    return op == ModifierOp::Shadow ? scene::kHiddenFromShadows
           : op == ModifierOp::Camera ? scene::kHiddenFromCamera
                                      : scene::kHiddenFromReflections;
}

void hide(ModifierList& list, uint8_t bits, SourceRange where) {
    if (!list.hidden) list.hiddenRange = where;
    list.hidden |= bits;
}

} // namespace

ModifierList Interpreter::evalModifiers(std::span<const Modifier> modifiers, SourceRange whole) {
    ModifierList list;
    list.range = whole;
    auto giveMaterial = [&](int32_t material, SourceRange where) {
        if (list.material >= 0) {
            Diagnostic& d = diagnostics_.error(where, "a second material in one list of modifiers");
            d.notes.push_back({list.materialRange, "the first is given here"});
            throw EvalError{};
        }
        list.material = material;
        list.materialRange = where;
    };
    for (const Modifier& m : modifiers) {
        switch (m.op) {
        case ModifierOp::Translate:
        case ModifierOp::Rotate:
        case ModifierOp::Scale: list.moves.push_back(evalMove(m)); break;
        case ModifierOp::Matrix: list.moves.push_back(evalMatrix(m)); break;
        case ModifierOp::Material: {
            Value arg = eval(m.argument);
            if (arg.kind != ValueKind::Material)
                fail(m.argument->range,
                     fmt::format("'material' takes a material, not {}", typeName(arg)));
            giveMaterial(static_cast<int32_t>(arg.index), m.range);
            break;
        }
        case ModifierOp::Shadow:
        case ModifierOp::Camera:
        case ModifierOp::Reflected: {
            Value arg = eval(m.argument);
            if (arg.kind != ValueKind::Bool)
                fail(m.argument->range, fmt::format("'{}' takes true or false, not {}", opSpelling(m.op), typeName(arg)));
            if (!arg.b) hide(list, hiddenBit(m.op), m.range);
            break;
        }
        case ModifierOp::Splice: {
            Value arg = eval(m.argument);
            if (arg.kind != ValueKind::Modifiers)
                fail(m.argument->range,
                     fmt::format("{} is not a list of modifiers; write <translate …>, <rotate …> "
                                 "or <scale …> to move by a vector",
                                 typeName(arg)));
            const ModifierList& given = *arg.modifiers;
            charge(given.moves.size() * sizeof(scene::Modifier));
            list.moves.insert(list.moves.end(), given.moves.begin(), given.moves.end());
            if (given.material >= 0) giveMaterial(given.material, m.range);
            if (given.hidden) hide(list, given.hidden, m.range);
            break;
        }
        }
    }
    return list;
}

Value Interpreter::evalModifierList(const ModifierListExpr* node) {
    ModifierList list = evalModifiers(node->modifiers, node->range);
    charge(sizeof(ModifierList) + list.moves.size() * sizeof(scene::Modifier));
    Value value;
    value.kind = ValueKind::Modifiers;
    value.modifiers = &modifierLists_.emplace_back(std::move(list));
    return value;
}

Value Interpreter::evalModify(const ModifyExpr* node) {
    Value target = eval(node->target);
    if (target.kind != ValueKind::Entity && target.kind != ValueKind::Texture) {
        fail(node->target->range,
             fmt::format("cannot apply modifiers to {}; only entities and textures move", typeName(target)));
    }
    ModifierList list = evalModifiers(node->modifiers, node->range);
    std::vector<scene::Modifier>& modifiers = list.moves;
    if (target.kind == ValueKind::Texture) {
        if (list.material >= 0)
            fail(list.materialRange, "a texture takes no material; 'material' is for entities");
        if (list.hidden)
            fail(list.hiddenRange, "a texture is not hidden from rays; 'shadow', 'camera' and 'reflected' are for entities");
        scene::TextureDesc texture = scene_.textures[target.index];
        texture.modifiers.insert(texture.modifiers.end(), modifiers.begin(), modifiers.end());
        texture.source = span(node->range);
        scene_.textures.push_back(std::move(texture));
        return Value::object(ValueKind::Texture, target.objectType,
                             static_cast<uint32_t>(scene_.textures.size() - 1));
    }
    // Modifying a transformed entity extends its list rather than nesting transforms; a
    // material it gives already is nearer the parts, so it stays.
    int32_t child = static_cast<int32_t>(target.index);
    int32_t material = list.material;
    uint8_t hidden = 0; // the replaced transform's, which hides what it moved
    if (auto* inner = std::get_if<scene::TransformNode>(&scene_.entities[target.index].shape)) {
        hidden = scene_.entities[target.index].hidden;
        charge((inner->modifiers.size() + modifiers.size()) * sizeof(scene::Modifier));
        std::vector<scene::Modifier> combined = inner->modifiers;
        combined.insert(combined.end(), modifiers.begin(), modifiers.end());
        modifiers = std::move(combined);
        child = inner->child;
        if (scene_.entities[target.index].material >= 0)
            material = scene_.entities[target.index].material;
    }
    bool solid = scene_.entities[static_cast<size_t>(child)].solid;
    int32_t index = addEntity(scene::EntityDesc{scene::TransformNode{child, std::move(modifiers)},
                                                material, solid, span(node->range),
                                                static_cast<uint8_t>(hidden | list.hidden)},
                              EntityInfo{node->range, target.objectType, false});
    return Value::object(ValueKind::Entity, target.objectType, static_cast<uint32_t>(index));
}

void Interpreter::arityError(const BuiltinInfo& info, const CallExpr* node) {
    int count = static_cast<int>(node->args.size());
    std::string expected = info.minArgs == info.maxArgs
                               ? fmt::format("{}", info.minArgs)
                               : info.maxArgs < 0 ? fmt::format("at least {}", info.minArgs)
                                                  : fmt::format("{} to {}", info.minArgs, info.maxArgs);
    bool singular = info.maxArgs == 1 || (info.maxArgs < 0 && info.minArgs == 1);
    Diagnostic& d = diagnostics_.error(node->range, fmt::format("{} takes {} argument{}, but {} {} given",
                                                                info.name, expected, singular ? "" : "s",
                                                                count, count == 1 ? "was" : "were"));
    d.notes.push_back({node->callee->range, fmt::format("signature: {}", info.signature)});
    throw EvalError{};
}

// Inline in evalCall (its only caller), for both places the arguments can live.
[[gnu::always_inline]] inline Value Interpreter::callWith(const Value& callee, const CallExpr* node, std::span<Value> args) {
    evalArguments(node, args);
    if (callee.kind == ValueKind::Macro) return callMacro(callee.closure, node, args);
    if (callee.kind == ValueKind::Function) return callFunction(callee.index, node, args);
    // sin(x) and its kind on a number, the loops' usual call, skip the general path; a NaN
    // result goes the general way, where the built-in tells a domain error from a NaN given.
    if (args.size() == 1 && args[0].isNumber()) {
        if (UnaryMath math = unaryMath(callee.index)) {
            double result = math(args[0].asDouble());
            if (!std::isnan(result)) return Value::number(result);
        }
    }
    const BuiltinInfo& info = builtinFunctions()[callee.index];
    if (!arityFits(info, node->args.size())) arityError(info, node);
    BuiltinCall call{*this, node, args};
    return info.function(call);
}

Value Interpreter::evalCall(const CallExpr* node) {
    // A built-in's name (resolved statically, and never reassigned) needs no evaluation.
    const auto* name = node->callee->kind == NodeKind::Var ? static_cast<const VarExpr*>(node->callee) : nullptr;
    Value callee = name && name->resolution.binding == Binding::Builtin ? prelude_[name->resolution.slot]
                                                                         : eval(node->callee);
    if (callee.kind != ValueKind::Builtin && callee.kind != ValueKind::Macro &&
        callee.kind != ValueKind::Function) {
        fail(node->callee->range, fmt::format("cannot call {}; only macros and functions can be called",
                                              typeName(callee)));
    }
    // Arguments evaluate left to right, before the call. Most calls have a few: they stay
    // on the C++ stack (Value is an implicit-lifetime type: the bytes need no constructor).
    constexpr size_t kOnStack = 8;
    if (node->args.size() > kOnStack) [[unlikely]] {
        std::vector<Value> many(node->args.size());
        return callWith(callee, node, many);
    }
    alignas(Value) std::byte storage[kOnStack * sizeof(Value)];
    return callWith(callee, node, std::span<Value>(reinterpret_cast<Value*>(storage), node->args.size()));
}

} // namespace crt::lang
