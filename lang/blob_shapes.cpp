// Blobs and their parts: BlobSphere and BlobCylinder values, and the Blob that adds up
// their fields.
#include "interpreter_impl.hpp"
#include "object_builder.hpp"

namespace crt::lang {

/// A Blob: a threshold above 0 (or the solid would reach infinity), and its components.
scene::Shape Interpreter::blobShape(ObjectBuilder& b) {
    auto desc = std::make_shared<scene::BlobDesc>();
    desc->threshold = b.number("threshold", desc->threshold);
    if (!(desc->threshold > 0)) {
        fail(b.where("threshold"),
             fmt::format("a Blob's threshold must be above 0, not {:g}: the field is 0 far away, "
                         "so the solid would fill space",
                         desc->threshold));
    }
    for (const Value& v : *b.get("components")->list)
        desc->components.push_back(blobComponents_[v.index].component);
    return scene::BlobShape{std::move(desc)};
}

Value Interpreter::buildBlobComponent(const ObjectBuilder& b) {
    scene::BlobComponent c;
    c.cylinder = b.info.type == ObjectType::BlobCylinder;
    c.a = b.vec(c.cylinder ? "base" : "center", c.a);
    c.b = b.vec("top", c.a);
    c.radius = b.number("radius", c.radius);
    c.strength = b.number("strength", c.strength);
    if (!(c.radius > 0))
        fail(b.where("radius"),
             fmt::format("a {}'s radius must be above 0, not {:g}", b.info.name, c.radius));
    if (c.cylinder && c.a == c.b)
        fail(b.where("top"), "a BlobCylinder needs 'base' and 'top' to differ");
    blobComponents_.push_back({c, span(b.range)});
    return Value::object(ValueKind::BlobComponent, b.info.type,
                         static_cast<uint32_t>(blobComponents_.size() - 1));
}

} // namespace crt::lang
