// Spellings of AST operators.
#include "ast.hpp"

namespace crt::lang {

std::string_view opSpelling(UnaryOp op) {
    switch (op) {
    case UnaryOp::Plus: return "+";
    case UnaryOp::Minus: return "-";
    case UnaryOp::Not: return "!";
    }
    return "?";
}

std::string_view opSpelling(BinaryOp op) {
    switch (op) {
    case BinaryOp::Add: return "+";
    case BinaryOp::Sub: return "-";
    case BinaryOp::Intersect: return "^";
    case BinaryOp::Mul: return "*";
    case BinaryOp::Div: return "/";
    case BinaryOp::Mod: return "%";
    case BinaryOp::Less: return "<";
    case BinaryOp::Greater: return ">";
    case BinaryOp::LessEqual: return "<=";
    case BinaryOp::GreaterEqual: return ">=";
    case BinaryOp::Equal: return "==";
    case BinaryOp::NotEqual: return "!=";
    case BinaryOp::And: return "&&";
    case BinaryOp::Or: return "||";
    }
    return "?";
}

std::string_view opSpelling(ModifierOp op) {
    switch (op) {
    case ModifierOp::Translate: return "translate";
    case ModifierOp::Rotate: return "rotate";
    case ModifierOp::Scale: return "scale";
    case ModifierOp::Material: return "material";
    case ModifierOp::Matrix: return "matrix";
    case ModifierOp::Shadow: return "shadow";
    case ModifierOp::Camera: return "camera";
    case ModifierOp::Reflected: return "reflected";
    case ModifierOp::Splice: return "";
    }
    return "?";
}

std::optional<ModifierOp> namedModifier(std::string_view word) {
    for (ModifierOp op : {ModifierOp::Material, ModifierOp::Matrix, ModifierOp::Shadow, ModifierOp::Camera,
                          ModifierOp::Reflected})
        if (word == opSpelling(op)) return op;
    return std::nullopt;
}

} // namespace crt::lang
