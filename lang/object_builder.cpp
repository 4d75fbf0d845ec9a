// Object literals' attributes (spec §5): evaluated in order and checked against the schema.
#include "object_builder.hpp"

#include "scene/entity_parts.hpp"

#include <cmath>
#include <filesystem>

namespace crt::lang {

namespace fs = std::filesystem;

SourceRange itemRange(const Expr* value, size_t index) {
    if (value->kind == NodeKind::List) {
        auto* list = static_cast<const ListExpr*>(value);
        if (index < list->items.size()) return list->items[index]->range;
    }
    return value->range;
}

namespace {

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

/// What the fix-it for a missing attribute of this type writes.
std::string_view placeholder(AttrType type) {
    switch (type) {
    case AttrType::Vec3: return "vec3(0, 0, 0)";
    case AttrType::Color: return "rgb(1, 1, 1)";
    case AttrType::String: return "\"\"";
    case AttrType::Int: return "1";
    default: return "1.0";
    }
}

} // namespace

void ObjectBuilder::evaluate(std::span<const Attribute> attributes) {
    // An attribute whose value fails is poisoned and the next one is read, so that every
    // wrong attribute is reported; the object is then not built.
    uint32_t poisonedMask = 0;
    for (const Attribute& a : attributes) {
        try {
            Value v = in.eval(a.value);
            if (a.slot < 0) continue; // reported by the resolver
            check(a, v);
            const auto slot = static_cast<size_t>(a.slot);
            new (&values[slot].value) Value(v);
            if (!isGiven(slot)) {
                givenSlots.push_back(static_cast<uint8_t>(slot));
                givenMask |= 1u << slot;
            }
            given[slot] = &a;
        } catch (const EvalError&) {
            if (in.stopped_) throw;
            if (a.slot >= 0) poisonedMask |= 1u << a.slot;
        }
    }
    bool complete = poisonedMask == 0;
    for (size_t i = 0; i < info.attributes.size(); ++i) {
        if (info.attributes[i].required && !isGiven(i) && !((poisonedMask >> i) & 1u)) {
            missing(info.attributes[i]);
            complete = false;
        }
    }
    if (!complete) throw EvalError{};
}

void ObjectBuilder::missing(const AttributeInfo& attr) {
    Diagnostic& d = in.diagnostics_.error(
        typeRange, fmt::format("{} is missing its required attribute '{}'", info.name, attr.name));
    uint32_t closing = range.end > range.begin ? range.end - 1 : range.end;
    d.fixits.push_back({{range.file, closing, closing},
                        fmt::format("{} -> {} ", attr.name, placeholder(attr.type))});
}

void ObjectBuilder::wrongType(const Attribute& a, const Value& v, std::string_view wanted) {
    in.fail(a.value->range, fmt::format("attribute '{}' of {} must be {}, not {}", a.name,
                                        info.name, wanted, typeName(v)));
}

void ObjectBuilder::floatForInt(const Attribute& a, const Value& v, std::string_view wanted) {
    Diagnostic& d = in.diagnostics_.error(
        a.value->range,
        fmt::format("attribute '{}' of {} must be {}, not float", a.name, info.name, wanted));
    addIntFixIt(d, v, a.value->range);
    throw EvalError{};
}

void ObjectBuilder::finite(const Attribute& a, const Value& v, int components) {
    for (int k = 0; k < components; ++k) {
        double x = components == 1 ? v.asDouble() : v.v[k];
        if (!std::isfinite(x)) {
            in.fail(a.value->range,
                    fmt::format("attribute '{}' of {} is {}; it must be finite", a.name, info.name,
                                components == 1 ? formatFloat(x) : in.str(v)));
        }
    }
}

void ObjectBuilder::check(const Attribute& a, const Value& v) {
    const AttributeInfo& attr = info.attributes[static_cast<size_t>(a.slot)];
    switch (attr.type) {
    case AttrType::Float:
    case AttrType::Int:
    case AttrType::Vec3:
    case AttrType::Color: checkNumber(a, v, attr.type); return;
    case AttrType::Bool:
        if (v.kind != ValueKind::Bool) wrongType(a, v, "a bool");
        return;
    case AttrType::String:
        if (v.kind != ValueKind::String) wrongType(a, v, "a string");
        return;
    case AttrType::Choice:
        if (v.kind != ValueKind::String) wrongType(a, v, "a string");
        checkChoice(a, v, attr);
        return;
    case AttrType::Material:
    case AttrType::Camera:
    case AttrType::Background:
    case AttrType::Fog:
    case AttrType::Medium:
    case AttrType::LightList:
    case AttrType::Texture:
    case AttrType::Bump: checkReference(a, v, attr.type); return;
    case AttrType::Gamma: checkGamma(a, v); return;
    case AttrType::Aperture: checkAperture(a, v, attr); return;
    case AttrType::ColorMap:
    case AttrType::MaterialMap: checkMap(a, v, attr.type); return;
    case AttrType::MaterialList: checkMaterialList(a, v); return;
    case AttrType::PatternList: checkPatternList(a, v); return;
    case AttrType::FloatOrPattern:
        if (v.isNumber()) {
            finite(a, v, 1);
        } else if (v.kind != ValueKind::Texture || !isColorTexture(v.objectType) || v.objectType == ObjectType::Image) {
            wrongType(a, v, "a float or a pattern (such as Bozo or Granite)");
        }
        return;
    case AttrType::Solid:
        if (!isSolid(v))
            notSolid(a.value->range, fmt::format("attribute '{}' of {}", a.name, info.name), v);
        return;
    case AttrType::SolidList: checkSolidList(a, v); return;
    case AttrType::Entity:
        if (v.kind != ValueKind::Entity) wrongType(a, v, "an entity");
        return;
    case AttrType::FloatList:
        if (v.kind != ValueKind::List) wrongType(a, v, "a list of numbers");
        for (size_t i = 0; i < v.list->size(); ++i) {
            const Value& item = (*v.list)[i];
            if (!item.isNumber() || !std::isfinite(item.asDouble())) {
                in.fail(itemRange(a.value, i),
                        fmt::format("item {} of '{}' must be a finite number, not {}", i + 1,
                                    a.name, typeName(item)));
            }
        }
        return;
    case AttrType::BlobComponentList:
        if (v.kind != ValueKind::List) wrongType(a, v, "a list of BlobSphere and BlobCylinder");
        if (v.list->empty()) in.fail(a.value->range, "a Blob needs at least one component");
        for (size_t i = 0; i < v.list->size(); ++i) {
            const Value& item = (*v.list)[i];
            if (item.kind != ValueKind::BlobComponent) {
                in.fail(
                    itemRange(a.value, i),
                    fmt::format("item {} of '{}' must be a BlobSphere or a BlobCylinder, not {}",
                                i + 1, a.name, typeName(item)));
            }
        }
        return;
    case AttrType::PointList:
        if (v.kind != ValueKind::List) wrongType(a, v, "a list of vec3");
        for (size_t i = 0; i < v.list->size(); ++i) {
            const Value& point = (*v.list)[i];
            if (point.kind != ValueKind::Vec3) {
                in.fail(itemRange(a.value, i), fmt::format("item {} of '{}' must be a vec3, not {}",
                                                           i + 1, a.name, typeName(point)));
            }
            for (int k = 0; k < 3; ++k)
                if (!std::isfinite(point.v[k]))
                    in.fail(itemRange(a.value, i),
                            fmt::format("item {} of '{}' is not finite", i + 1, a.name));
        }
        return;
    case AttrType::FaceList:
        if (v.kind != ValueKind::List) wrongType(a, v, "a list of [a, b, c]");
        for (size_t i = 0; i < v.list->size(); ++i) {
            const Value& face = (*v.list)[i];
            const bool triple = face.kind == ValueKind::List && face.list->size() == 3 &&
                                std::all_of(face.list->begin(), face.list->end(), [](const Value& n) {
                                    return n.kind == ValueKind::Int && n.i >= 0;
                                });
            if (!triple)
                in.fail(itemRange(a.value, i),
                        fmt::format("item {} of '{}' must be three vertex numbers [a, b, c], ints from 0",
                                    i + 1, a.name));
        }
        return;
    case AttrType::Function:
        if (v.kind != ValueKind::Function) wrongType(a, v, "a Function");
        if (size_t n = in.functionProgram(v.index)->parameterCount(); n != 3) {
            in.fail(a.value->range, fmt::format("attribute '{}' of {} takes a Function of (x, y, z), "
                                                "not one of {} parameter{}",
                                                a.name, info.name, n, n == 1 ? "" : "s"));
        }
        return;
    case AttrType::Box:
        if (v.kind != ValueKind::Entity || v.objectType != ObjectType::Box) wrongType(a, v, "a Box");
        if (!std::holds_alternative<scene::BoxShape>(in.scene_.entities[v.index].shape)) {
            in.fail(a.value->range, fmt::format("attribute '{}' of {} takes a Box as written, not "
                                                "moved: move the {} instead",
                                                a.name, info.name, info.name));
        }
        return;
    case AttrType::Turbulence:
        if (v.kind == ValueKind::Vec3) {
            finite(a, v, 3);
            return;
        }
        if (!v.isNumber()) wrongType(a, v, "a float or a vec3");
        finite(a, v, 1);
        return;
    }
}

/// A colour map or a material map: at least two [value, item] entries, values from 0 to 1
/// and in order.
void ObjectBuilder::checkMap(const Attribute& a, const Value& v, AttrType type) {
    const bool colours = type == AttrType::ColorMap;
    const std::string_view map = colours ? "colour map" : "material map";
    const std::string_view entry = colours ? "stop" : "entry";
    const std::string_view item = colours ? "colour" : "material";
    if (v.kind != ValueKind::List) {
        wrongType(a, v, fmt::format("a {}: a list of [value, {}]", map, item));
    }
    const std::vector<Value>& entries = *v.list;
    if (entries.size() < 2) {
        in.fail(a.value->range, fmt::format("a {} needs at least 2 {}, not {}", map,
                                            colours ? "stops" : "entries", entries.size()));
    }
    double previous = 0;
    for (size_t i = 0; i < entries.size(); ++i) {
        const Value& e = entries[i];
        SourceRange where = itemRange(a.value, i);
        if (e.kind != ValueKind::List || e.list->size() != 2 || !(*e.list)[0].isNumber() ||
            (*e.list)[1].kind != (colours ? ValueKind::Color : ValueKind::Material)) {
            in.fail(where, fmt::format("{} {} of the {} must be [value, {}], not {}", entry, i + 1,
                                       map, item, in.str(e)));
        }
        double value = (*e.list)[0].asDouble();
        if (!(value >= 0 && value <= 1)) {
            in.fail(where, fmt::format("{} {} of the {} is at {}; {}s lie from 0 to 1", entry,
                                       i + 1, map, formatFloat(value), colours ? "stop" : "value"));
        }
        if (value < previous) {
            in.fail(where, fmt::format("{} {} of the {} ({}) comes before the one ahead of it "
                                       "({}); {}s go in order",
                                       entry, i + 1, map, formatFloat(value), formatFloat(previous),
                                       colours ? "stop" : "value"));
        }
        for (int k = 0; colours && k < 4; ++k) {
            if (!std::isfinite((*e.list)[1].v[k])) {
                in.fail(where, fmt::format("stop {} of the colour map has a colour that is not "
                                           "finite",
                                           i + 1));
            }
        }
        previous = value;
    }
}

/// Layered's materials: a non-empty list of materials, bottom first.
void ObjectBuilder::checkMaterialList(const Attribute& a, const Value& v) {
    if (v.kind != ValueKind::List) wrongType(a, v, "a list of materials");
    if (v.list->empty()) in.fail(a.value->range, "a Layered needs at least one material");
    for (size_t i = 0; i < v.list->size(); ++i) {
        const Value& layer = (*v.list)[i];
        if (layer.kind != ValueKind::Material) {
            in.fail(itemRange(a.value, i),
                    fmt::format("layer {} must be a material, not {}", i + 1, typeName(layer)));
        }
    }
}

/// A non-empty list of patterns: textures that are neither a bump nor an image.
void ObjectBuilder::checkPatternList(const Attribute& a, const Value& v) {
    if (v.kind != ValueKind::List) wrongType(a, v, "a list of patterns");
    if (v.list->empty()) in.fail(a.value->range, fmt::format("'{}' needs at least one pattern", a.name));
    for (size_t i = 0; i < v.list->size(); ++i) {
        const Value& item = (*v.list)[i];
        if (item.kind != ValueKind::Texture || !isColorTexture(item.objectType) ||
            item.objectType == ObjectType::Image) {
            in.fail(itemRange(a.value, i),
                    fmt::format("item {} must be a pattern (such as Gradient or Bozo), not {}", i + 1, typeName(item)));
        }
    }
}

bool ObjectBuilder::isSolid(const Value& v) const {
    return v.kind == ValueKind::Entity && in.scene_.entities[v.index].solid;
}

void ObjectBuilder::notSolid(SourceRange where, std::string_view subject, const Value& v) {
    if (v.kind == ValueKind::Entity) {
        if (std::string open = in.openMeshReason(v.index); !open.empty())
            in.fail(where, fmt::format("{} must be a solid, and this Mesh is not closed: {}",
                                       subject, open));
    }
    in.fail(where, fmt::format("{} must be a solid ({}), not {}", subject, solidTypeList(),
                               typeName(v)));
}

void ObjectBuilder::checkSolidList(const Attribute& a, const Value& v) {
    if (v.kind != ValueKind::List) wrongType(a, v, "a list of solids");
    if (v.list->empty())
        in.fail(a.value->range, fmt::format("a {} needs at least one solid", info.name));
    for (size_t i = 0; i < v.list->size(); ++i) {
        const Value& item = (*v.list)[i];
        if (!isSolid(item))
            notSolid(itemRange(a.value, i), fmt::format("item {} of '{}'", i + 1, a.name), item);
    }
}

/// Numbers and vectors: the right kind, every component finite.
void ObjectBuilder::checkNumber(const Attribute& a, const Value& v, AttrType type) {
    switch (type) {
    case AttrType::Float:
        if (!v.isNumber()) wrongType(a, v, "a float");
        finite(a, v, 1);
        return;
    case AttrType::Int:
        if (v.kind == ValueKind::Float) floatForInt(a, v, "an int");
        if (v.kind != ValueKind::Int) wrongType(a, v, "an int");
        return;
    case AttrType::Vec3:
        if (v.kind != ValueKind::Vec3) wrongType(a, v, "a vec3");
        finite(a, v, 3);
        return;
    default:
        if (v.kind != ValueKind::Color) wrongType(a, v, "a colour");
        finite(a, v, 4);
        return;
    }
}

/// Attributes naming other objects: a material, a camera, lights, textures, a background.
void ObjectBuilder::checkReference(const Attribute& a, const Value& v, AttrType type) {
    switch (type) {
    case AttrType::Material:
        if (v.kind != ValueKind::Material) wrongType(a, v, "a Material");
        return;
    case AttrType::Camera:
        if (v.kind != ValueKind::Camera) wrongType(a, v, "a Camera");
        return;
    case AttrType::Background:
        if (v.kind != ValueKind::Background && v.kind != ValueKind::Color) {
            wrongType(a, v, "a Background or a colour");
        }
        if (v.kind == ValueKind::Color) finite(a, v, 4);
        return;
    case AttrType::Fog:
        if (v.kind != ValueKind::Fog) wrongType(a, v, "a Fog");
        return;
    case AttrType::Medium:
        if (v.kind != ValueKind::Medium) wrongType(a, v, "a Medium");
        return;
    case AttrType::LightList:
        if (v.kind != ValueKind::List) wrongType(a, v, "a list of lights");
        for (const Value& item : *v.list) {
            if (item.kind != ValueKind::Light) {
                in.fail(a.value->range, fmt::format("attribute 'lights' must hold only lights, "
                                                    "not {}",
                                                    typeName(item)));
            }
        }
        return;
    case AttrType::Texture:
        if (v.kind != ValueKind::Texture || !isColorTexture(v.objectType)) {
            wrongType(a, v, "a texture (a pattern such as Checker or Gradient, or an Image)");
        }
        return;
    default:
        if (v.kind != ValueKind::Texture || !isBumpTexture(v.objectType)) {
            wrongType(a, v, "a bump texture (Bump, NoiseBump or ImageBump)");
        }
        return;
    }
}

void ObjectBuilder::checkGamma(const Attribute& a, const Value& v) {
    if (v.kind == ValueKind::String) {
        if (!equalsIgnoringCase(*v.s, "srgb")) {
            in.fail(a.value->range,
                    fmt::format("gamma must be a number or \"srgb\", not \"{}\"", *v.s));
        }
        return;
    }
    if (!v.isNumber()) wrongType(a, v, "a float or \"srgb\"");
    finite(a, v, 1);
    if (v.asDouble() <= 0) in.fail(a.value->range, "gamma must be positive");
}

void ObjectBuilder::checkAperture(const Attribute& a, const Value& v, const AttributeInfo& attr) {
    if (v.kind == ValueKind::Int) {
        if (v.i < 3) in.fail(a.value->range, "a polygonal aperture needs at least 3 sides");
        return;
    }
    if (v.kind == ValueKind::Float) floatForInt(a, v, "a shape name or a number of sides");
    if (v.kind != ValueKind::String) wrongType(a, v, "a shape name or a number of sides");
    checkChoice(a, v, attr);
}

void ObjectBuilder::checkChoice(const Attribute& a, const Value& v, const AttributeInfo& attr) {
    for (std::string_view choice : attr.choices) {
        if (equalsIgnoringCase(*v.s, choice)) return;
    }
    std::string list;
    for (std::string_view choice : attr.choices) {
        list += fmt::format("{}\"{}\"", list.empty() ? "" : ", ", choice);
    }
    std::vector<std::string_view> names(attr.choices.begin(), attr.choices.end());
    std::string suggestion = closestMatch(*v.s, names);
    Diagnostic& d = in.diagnostics_.error(
        a.value->range,
        fmt::format("\"{}\" is not a valid {}; expected one of {}", *v.s, a.name, list));
    if (!suggestion.empty()) {
        d.message += fmt::format("; did you mean \"{}\"?", suggestion);
        d.fixits.push_back({a.value->range, fmt::format("\"{}\"", suggestion)});
    }
    throw EvalError{};
}

fs::path folderOf(const std::string& path) {
    std::error_code error;
    fs::path parent = fs::path(path).parent_path();
    fs::path folder = fs::absolute(parent.empty() ? fs::path(".") : parent, error);
    return folder.lexically_normal();
}

void addIntFixIt(Diagnostic& diagnostic, const Value& given, SourceRange where) {
    if (given.kind != ValueKind::Float || !std::isfinite(given.f) || std::abs(given.f) >= 9e15) {
        return;
    }
    std::string fixed = fmt::format("{}", static_cast<int64_t>(std::llround(given.f)));
    diagnostic.message += fmt::format("; use {}", fixed);
    diagnostic.fixits.push_back({where, fixed});
}

} // namespace crt::lang
