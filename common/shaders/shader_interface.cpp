// The interface check of live reload (shader_interface.hpp), by SPIRV-Cross reflection.
//
// The build's SPIR-V is taken with everything it declares: the C++ made the pipeline for it. The
// edited SPIR-V is taken with what its code uses. The edited shader fits when
//   - every descriptor it uses is one the build's declares at that (set, binding), of the same
//     kind, image type (dimensionality, arrayed, multisampled, depth, sampled type, storage
//     format) and input attachment index, and an array no longer than the build's;
//   - every member of a uniform or storage block, or of the push constants, that it uses lies
//     within the build's block, at the offset where the build's has a member of the same type and
//     layout (strides, row-major); a runtime array matches the build's runtime array;
//   - it reads no input location the build's does not declare with that type, still writes
//     every output location the build's declares, with that type, and writes no other;
//   - a specialization constant with an ID the build's has keeps its type (the C++ sets it with
//     that many bytes); a new ID keeps its default, which is valid;
//   - a compute shader keeps its local size (literal or the same constant IDs): the dispatch is
//     sized for it.
// Using fewer descriptors, members, inputs or push constants is always safe.
#include "common/shaders/shader_interface.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>

#include "common/core/check.hpp"

#if defined(VKBOOK_RUNTIME_SHADERS)
#include <spirv_cross/spirv_cross_c.h>
#endif

namespace common {

#if defined(VKBOOK_RUNTIME_SHADERS)
namespace {

struct Member {
    std::string name;
    size_t offset = 0, size = 0;  // size 0: a runtime array
    std::string type;             // GLSL spelling, for messages
    std::string layout;           // type, offsets, strides and majorness: what must be equal
};

struct Block {
    std::string name;
    size_t size = 0;              // declared size, runtime array excluded
    std::vector<Member> members;  // every member
    std::vector<unsigned> used;   // indices of the members the code reads or writes
};

struct Descriptor {
    std::string kind;  // "uniform block", "storage block", "combined image sampler", ...
    std::string name;
    std::string type;           // image type ("sampler2D", "image2D rgba16f"), empty for blocks and samplers
    unsigned count = 1;         // array length; 0: runtime-sized
    std::string countConstant;  // the array is sized by a specialization constant: which
    unsigned inputIndex = 0;
    bool writable = false;  // a storage block or image without readonly
    std::optional<Block> block;
};

struct Variable {
    std::string name, type;
};

struct Interface {
    // Every variable at each (set, binding): GLSL lets two of them share one.
    std::map<std::pair<unsigned, unsigned>, std::vector<Descriptor>> descriptors;
    std::vector<std::string> capabilities;  // OpCapability, sorted
    std::optional<Block> pushConstants;
    std::map<unsigned, Variable> inputs, outputs;
    std::map<unsigned, Variable> constants;  // constant_id -> name, type
    std::string localSize;                   // compute shaders: "8 x 8 x 1"
};

class Reflection {
public:
    explicit Reflection(const std::vector<uint32_t>& spirv) {
        if (spvc_context_create(&context_) != SPVC_SUCCESS) throw Failure("SPIRV-Cross: no context");
        spvc_parsed_ir ir = nullptr;
        if (spvc_context_parse_spirv(context_, spirv.data(), spirv.size(), &ir) != SPVC_SUCCESS ||
            spvc_context_create_compiler(context_, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                         &compiler_) != SPVC_SUCCESS)
            throw Failure(std::string("SPIRV-Cross: ") + spvc_context_get_last_error_string(context_));
    }
    ~Reflection() { spvc_context_destroy(context_); }
    Reflection(const Reflection&) = delete;
    Reflection& operator=(const Reflection&) = delete;

    Interface reflect(bool usedOnly);
    // Every specialization constant's ID and the bytes Vulkan takes for its value (a bool: 4).
    void constantSizes(std::map<unsigned, uint32_t>& sizes) const {
        const spvc_specialization_constant* constants = nullptr;
        size_t count = 0;
        spvc_compiler_get_specialization_constants(compiler_, &constants, &count);
        for (size_t i = 0; i < count; ++i) {
            spvc_type t =
                type(spvc_constant_get_type(spvc_compiler_get_constant_handle(compiler_, constants[i].id)));
            bool boolean = spvc_type_get_basetype(t) == SPVC_BASETYPE_BOOLEAN;
            sizes[constants[i].constant_id] = boolean ? 4u : spvc_type_get_bit_width(t) / 8u;
        }
    }

private:
    spvc_type type(spvc_type_id id) const { return spvc_compiler_get_type_handle(compiler_, id); }
    std::string typeName(spvc_type_id id) const;
    std::string arraySuffix(spvc_type t) const;
    std::string imageType(spvc_type_id id) const;
    std::string layoutOf(spvc_type_id id) const;
    Block block(const spvc_reflected_resource& resource, bool usedOnly) const;
    std::string name(spvc_variable_id id) const {
        const char* n = spvc_compiler_get_name(compiler_, id);
        return n && *n ? n : "unnamed";
    }

    spvc_context context_ = nullptr;
    spvc_compiler compiler_ = nullptr;
};

std::string Reflection::arraySuffix(spvc_type t) const {
    std::string suffix;
    for (unsigned d = spvc_type_get_num_array_dimensions(t); d-- > 0;) {
        SpvId length = spvc_type_get_array_dimension(t, d);
        suffix += '[';
        if (!spvc_type_array_dimension_is_literal(t, d))
            suffix += "constant";
        else if (length != 0)
            suffix += std::to_string(length);
        suffix += ']';
    }
    return suffix;
}

std::string Reflection::typeName(spvc_type_id id) const {
    spvc_type t = type(id);
    spvc_basetype base = spvc_type_get_basetype(t);
    std::string name;
    if (base == SPVC_BASETYPE_STRUCT) {
        const char* n = spvc_compiler_get_name(compiler_, spvc_type_get_base_type_id(t));
        name = std::string("struct ") + (n && *n ? n : "unnamed");
    } else if (base == SPVC_BASETYPE_IMAGE || base == SPVC_BASETYPE_SAMPLED_IMAGE) {
        name = imageType(id);
    } else {
        const char* scalar = "?";
        const char* prefix = "?";
        switch (base) {
            case SPVC_BASETYPE_BOOLEAN:
                scalar = "bool", prefix = "b";
                break;
            case SPVC_BASETYPE_INT32:
                scalar = "int", prefix = "i";
                break;
            case SPVC_BASETYPE_UINT32:
                scalar = "uint", prefix = "u";
                break;
            case SPVC_BASETYPE_FP32:
                scalar = "float", prefix = "";
                break;
            case SPVC_BASETYPE_FP64:
                scalar = "double", prefix = "d";
                break;
            case SPVC_BASETYPE_INT64:
                scalar = "int64_t", prefix = "i64";
                break;
            case SPVC_BASETYPE_UINT64:
                scalar = "uint64_t", prefix = "u64";
                break;
            case SPVC_BASETYPE_INT16:
                scalar = "int16_t", prefix = "i16";
                break;
            case SPVC_BASETYPE_UINT16:
                scalar = "uint16_t", prefix = "u16";
                break;
            case SPVC_BASETYPE_FP16:
                scalar = "float16_t", prefix = "f16";
                break;
            case SPVC_BASETYPE_INT8:
                scalar = "int8_t", prefix = "i8";
                break;
            case SPVC_BASETYPE_UINT8:
                scalar = "uint8_t", prefix = "u8";
                break;
            case SPVC_BASETYPE_SAMPLER:
                scalar = "sampler";
                break;
            default:
                break;
        }
        unsigned columns = spvc_type_get_columns(t), rows = spvc_type_get_vector_size(t);
        if (columns > 1)
            name = std::string(prefix) + "mat" + std::to_string(columns) +
                   (rows == columns ? "" : "x" + std::to_string(rows));
        else if (rows > 1)
            name = std::string(prefix) + "vec" + std::to_string(rows);
        else
            name = scalar;
    }
    return name + arraySuffix(t);
}

std::string Reflection::imageType(spvc_type_id id) const {
    spvc_type t = type(id);
    bool storage = spvc_type_get_basetype(t) == SPVC_BASETYPE_IMAGE && spvc_type_get_image_is_storage(t);
    const char* word = spvc_type_get_basetype(t) == SPVC_BASETYPE_SAMPLED_IMAGE ? "sampler"
                       : storage                                                ? "image"
                                                                                : "texture";
    std::string prefix;
    switch (spvc_type_get_basetype(type(spvc_type_get_image_sampled_type(t)))) {
        case SPVC_BASETYPE_INT32:
            prefix = "i";
            break;
        case SPVC_BASETYPE_UINT32:
            prefix = "u";
            break;
        default:
            break;
    }
    std::string dim;
    switch (spvc_type_get_image_dimension(t)) {
        case SpvDim1D:
            dim = "1D";
            break;
        case SpvDim2D:
            dim = "2D";
            break;
        case SpvDim3D:
            dim = "3D";
            break;
        case SpvDimCube:
            dim = "Cube";
            break;
        case SpvDimRect:
            dim = "2DRect";
            break;
        case SpvDimBuffer:
            dim = "Buffer";
            break;
        case SpvDimSubpassData:
            return prefix + "subpassInput" + (spvc_type_get_image_multisampled(t) ? "MS" : "");
        default:
            dim = "?";
            break;
    }
    std::string name = prefix + word + dim + (spvc_type_get_image_multisampled(t) ? "MS" : "") +
                       (spvc_type_get_image_arrayed(t) ? "Array" : "") +
                       (spvc_type_get_image_is_depth(t) && !storage ? "Shadow" : "");
    if (storage) {
        static const std::map<SpvImageFormat, const char*> kFormats = {
            {SpvImageFormatUnknown, "no format"}, {SpvImageFormatRgba32f, "rgba32f"},
            {SpvImageFormatRgba16f, "rgba16f"},   {SpvImageFormatR32f, "r32f"},
            {SpvImageFormatRgba8, "rgba8"},       {SpvImageFormatRg32f, "rg32f"},
            {SpvImageFormatRg16f, "rg16f"},       {SpvImageFormatR16f, "r16f"},
            {SpvImageFormatR32ui, "r32ui"},       {SpvImageFormatRgba32ui, "rgba32ui"},
            {SpvImageFormatR32i, "r32i"},         {SpvImageFormatRgba16, "rgba16"},
        };
        SpvImageFormat format = spvc_type_get_image_storage_format(t);
        auto known = kFormats.find(format);
        name += " " + (known != kFormats.end() ? std::string(known->second)
                                               : "format " + std::to_string(unsigned(format)));
    }
    return name;
}

// Everything about a type that decides where its bytes are: for structs every member's offset,
// array and matrix stride and majorness, recursively.
std::string Reflection::layoutOf(spvc_type_id id) const {
    spvc_type t = type(id);
    if (spvc_type_get_basetype(t) != SPVC_BASETYPE_STRUCT) return typeName(id);
    std::string layout = "struct" + arraySuffix(t) + " {";  // its name is not part of its layout
    for (unsigned i = 0; i < spvc_type_get_num_member_types(t); ++i) {
        unsigned offset = 0, arrayStride = 0, matrixStride = 0;
        spvc_compiler_type_struct_member_offset(compiler_, t, i, &offset);
        spvc_type_id memberType = spvc_type_get_member_type(t, i);
        if (spvc_type_get_num_array_dimensions(type(memberType)) > 0)
            spvc_compiler_type_struct_member_array_stride(compiler_, t, i, &arrayStride);
        if (spvc_type_get_columns(type(memberType)) > 1)
            spvc_compiler_type_struct_member_matrix_stride(compiler_, t, i, &matrixStride);
        bool rowMajor = spvc_compiler_has_member_decoration(compiler_, spvc_type_get_base_type_id(t), i,
                                                            SpvDecorationRowMajor);
        layout += " @" + std::to_string(offset) + " " + layoutOf(memberType) + " a" +
                  std::to_string(arrayStride) + " m" + std::to_string(matrixStride) + (rowMajor ? " r" : "") +
                  ";";
    }
    return layout + " }";
}

Block Reflection::block(const spvc_reflected_resource& resource, bool usedOnly) const {
    Block result;
    spvc_type t = type(resource.base_type_id);
    const char* blockName = spvc_compiler_get_name(compiler_, resource.base_type_id);
    result.name = blockName && *blockName ? blockName : resource.name;
    spvc_compiler_get_declared_struct_size(compiler_, t, &result.size);
    unsigned count = spvc_type_get_num_member_types(t);
    for (unsigned i = 0; i < count; ++i) {
        Member member;
        const char* memberName = spvc_compiler_get_member_name(compiler_, resource.base_type_id, i);
        member.name = memberName && *memberName ? memberName : "member " + std::to_string(i);
        unsigned offset = 0;
        spvc_compiler_type_struct_member_offset(compiler_, t, i, &offset);
        member.offset = offset;
        spvc_compiler_get_declared_struct_member_size(compiler_, t, i, &member.size);
        spvc_type_id memberType = spvc_type_get_member_type(t, i);
        member.type = typeName(memberType);
        // The member's layout as the block sees it: its own, plus the strides the block gives it.
        unsigned arrayStride = 0, matrixStride = 0;
        if (spvc_type_get_num_array_dimensions(type(memberType)) > 0)
            spvc_compiler_type_struct_member_array_stride(compiler_, t, i, &arrayStride);
        if (spvc_type_get_columns(type(memberType)) > 1)
            spvc_compiler_type_struct_member_matrix_stride(compiler_, t, i, &matrixStride);
        bool rowMajor =
            spvc_compiler_has_member_decoration(compiler_, resource.base_type_id, i, SpvDecorationRowMajor);
        member.layout = layoutOf(memberType) + " a" + std::to_string(arrayStride) + " m" +
                        std::to_string(matrixStride) + (rowMajor ? " r" : "");
        result.members.push_back(member);
    }
    if (usedOnly) {
        const spvc_buffer_range* ranges = nullptr;
        size_t rangeCount = 0;
        spvc_compiler_get_active_buffer_ranges(compiler_, resource.id, &ranges, &rangeCount);
        for (size_t r = 0; r < rangeCount; ++r) result.used.push_back(ranges[r].index);
        std::sort(result.used.begin(), result.used.end());
        result.used.erase(std::unique(result.used.begin(), result.used.end()), result.used.end());
    } else {
        for (unsigned i = 0; i < count; ++i) result.used.push_back(i);
    }
    return result;
}

Interface Reflection::reflect(bool usedOnly) {
    Interface result;
    spvc_set active = nullptr;
    spvc_resources resources = nullptr;
    if (usedOnly) {
        spvc_compiler_get_active_interface_variables(compiler_, &active);
        spvc_compiler_create_shader_resources_for_active_variables(compiler_, &resources, active);
    } else {
        spvc_compiler_create_shader_resources(compiler_, &resources);
    }
    auto each = [&](spvc_resource_type kind, auto&& body) {
        const spvc_reflected_resource* list = nullptr;
        size_t count = 0;
        spvc_resources_get_resource_list_for_type(resources, kind, &list, &count);
        for (size_t i = 0; i < count; ++i) body(list[i]);
    };
    const std::pair<spvc_resource_type, const char*> kinds[] = {
        {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, "uniform block"},
        {SPVC_RESOURCE_TYPE_STORAGE_BUFFER, "storage block"},
        {SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, "combined image sampler"},
        {SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, "sampled image"},
        {SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, "sampler"},
        {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, "storage image"},
        {SPVC_RESOURCE_TYPE_SUBPASS_INPUT, "input attachment"},
    };
    for (const auto& [kind, kindName] : kinds)
        each(kind, [&](const spvc_reflected_resource& resource) {
            unsigned set = spvc_compiler_get_decoration(compiler_, resource.id, SpvDecorationDescriptorSet);
            unsigned binding = spvc_compiler_get_decoration(compiler_, resource.id, SpvDecorationBinding);
            Descriptor d;
            d.kind = kindName;
            d.name = resource.name;
            spvc_type variableType = type(resource.type_id);
            for (unsigned dim = 0; dim < spvc_type_get_num_array_dimensions(variableType); ++dim) {
                if (!spvc_type_array_dimension_is_literal(variableType, dim))
                    d.countConstant = name(spvc_type_get_array_dimension(variableType, dim));
                else
                    d.count *= spvc_type_get_array_dimension(variableType, dim);
            }
            if (kind == SPVC_RESOURCE_TYPE_UNIFORM_BUFFER || kind == SPVC_RESOURCE_TYPE_STORAGE_BUFFER)
                d.block = block(resource, usedOnly);
            else if (kind != SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS)
                d.type = imageType(resource.base_type_id);
            if (kind == SPVC_RESOURCE_TYPE_SUBPASS_INPUT)
                d.inputIndex =
                    spvc_compiler_get_decoration(compiler_, resource.id, SpvDecorationInputAttachmentIndex);
            if (kind == SPVC_RESOURCE_TYPE_STORAGE_IMAGE)
                d.writable = !spvc_compiler_has_decoration(compiler_, resource.id, SpvDecorationNonWritable);
            if (kind == SPVC_RESOURCE_TYPE_STORAGE_BUFFER) {
                // readonly on the block, or on every member.
                bool readonly =
                    spvc_compiler_has_decoration(compiler_, resource.id, SpvDecorationNonWritable);
                if (!readonly) {
                    readonly = true;
                    for (unsigned i = 0; i < spvc_type_get_num_member_types(type(resource.base_type_id)); ++i)
                        readonly =
                            readonly && spvc_compiler_has_member_decoration(compiler_, resource.base_type_id,
                                                                            i, SpvDecorationNonWritable);
                }
                d.writable = !readonly;
            }
            result.descriptors[{set, binding}].push_back(d);
        });
    each(SPVC_RESOURCE_TYPE_PUSH_CONSTANT,
         [&](const spvc_reflected_resource& resource) { result.pushConstants = block(resource, usedOnly); });
    each(SPVC_RESOURCE_TYPE_STAGE_INPUT, [&](const spvc_reflected_resource& resource) {
        unsigned location = spvc_compiler_get_decoration(compiler_, resource.id, SpvDecorationLocation);
        result.inputs[location] = {resource.name, typeName(resource.type_id)};
    });
    each(SPVC_RESOURCE_TYPE_STAGE_OUTPUT, [&](const spvc_reflected_resource& resource) {
        unsigned location = spvc_compiler_get_decoration(compiler_, resource.id, SpvDecorationLocation);
        result.outputs[location] = {resource.name, typeName(resource.type_id)};
    });

    const spvc_specialization_constant* constants = nullptr;
    size_t constantCount = 0;
    spvc_compiler_get_specialization_constants(compiler_, &constants, &constantCount);
    for (size_t i = 0; i < constantCount; ++i) {
        spvc_constant constant = spvc_compiler_get_constant_handle(compiler_, constants[i].id);
        result.constants[constants[i].constant_id] = {name(constants[i].id),
                                                      typeName(spvc_constant_get_type(constant))};
    }

    spvc_entry_point const* entryPoints = nullptr;
    size_t entryCount = 0;
    spvc_compiler_get_entry_points(compiler_, &entryPoints, &entryCount);
    if (entryCount > 0 && entryPoints[0].execution_model == SpvExecutionModelGLCompute) {
        spvc_specialization_constant ids[3]{};
        spvc_compiler_get_work_group_size_specialization_constants(compiler_, &ids[0], &ids[1], &ids[2]);
        for (unsigned axis = 0; axis < 3; ++axis) {
            if (axis > 0) result.localSize += " x ";
            if (ids[axis].id != 0)
                result.localSize += "constant " + std::to_string(ids[axis].constant_id);
            else
                result.localSize += std::to_string(spvc_compiler_get_execution_mode_argument_by_index(
                    compiler_, SpvExecutionModeLocalSize, axis));
        }
    }
    return result;
}

// The OpCapability instructions of a module, by name where we know it (SPIR-V's capability numbers).
std::vector<std::string> capabilities(const std::vector<uint32_t>& words) {
    static const std::map<uint32_t, const char*> kNames = {{0, "Matrix"},
                                                           {1, "Shader"},
                                                           {2, "Geometry"},
                                                           {3, "Tessellation"},
                                                           {9, "Float16"},
                                                           {10, "Float64"},
                                                           {11, "Int64"},
                                                           {12, "Int64Atomics"},
                                                           {22, "Int16"},
                                                           {32, "ImageGatherExtended"},
                                                           {35, "SampleRateShading"},
                                                           {39, "Int8"},
                                                           {40, "InputAttachment"},
                                                           {49, "StorageImageExtendedFormats"},
                                                           {43, "Sampled1D"},
                                                           {44, "Image1D"},
                                                           {46, "SampledBuffer"},
                                                           {47, "ImageBuffer"},
                                                           {50, "ImageQuery"},
                                                           {51, "DerivativeControl"},
                                                           {56, "StorageImageReadWithoutFormat"},
                                                           {57, "StorageImageWriteWithoutFormat"},
                                                           {61, "GroupNonUniform"}};
    std::vector<std::string> result;
    for (size_t at = 5; at < words.size();) {
        uint32_t count = words[at] >> 16, opcode = words[at] & 0xffff;
        if (count == 0) break;
        if (opcode == 17 && at + 1 < words.size()) {  // OpCapability
            auto known = kNames.find(words[at + 1]);
            result.push_back(known != kNames.end() ? known->second
                                                   : "number " + std::to_string(words[at + 1]));
        }
        at += count;
    }
    std::sort(result.begin(), result.end());
    return result;
}

std::string range(const Member& m) {
    if (m.size == 0) return "from byte " + std::to_string(m.offset);
    return "bytes " + std::to_string(m.offset) + ".." + std::to_string(m.offset + m.size - 1);
}

// The members `edited` uses against the block the pipeline was made for.
std::string blockChange(const std::string& where, const Block& built, const Block& edited) {
    for (unsigned index : edited.used) {
        const Member& m = edited.members[index];
        bool past = m.size == 0 ? m.offset > built.size : m.offset + m.size > built.size;
        auto same = std::find_if(built.members.begin(), built.members.end(),
                                 [&](const Member& b) { return b.offset == m.offset; });
        bool runtimeArrayThere = same != built.members.end() && same->size == 0;
        if (past && !runtimeArrayThere)
            return where + ": member " + m.name + " (" + m.type + ", " + range(m) + ") lies past the " +
                   std::to_string(built.size) + " bytes the shader its pipeline was made for declares";
        if (same == built.members.end())
            return where + ": member " + m.name + " (" + m.type + ", " + range(m) +
                   ") starts where the shader its pipeline was made for has no member";
        if (same->layout != m.layout) {
            if (same->type != m.type)
                return where + ": member " + m.name + " at byte " + std::to_string(m.offset) + " is " +
                       m.type + "; the shader its pipeline was made for has " + same->name + ", " +
                       same->type;
            return where + ": member " + m.name + " (" + m.type + ") at byte " + std::to_string(m.offset) +
                   " has another layout (strides or majorness) than in the shader its pipeline was made for";
        }
    }
    return {};
}

// "a sampler2D", "an input attachment".
std::string withArticle(const std::string& noun) {
    return (noun.find_first_of("aeio") == 0 ? "an " : "a ") + noun;  // "a uniform block"
}

std::string interfaceChange(const Interface& built, const Interface& edited) {
    // A capability the build's shader has not is refused unless every Vulkan 1.1 device has it
    // without a feature to enable (the rest need features this program does not turn on).
    static const std::vector<std::string> kAlways = {"DerivativeControl", "Image1D",         "ImageBuffer",
                                                     "ImageQuery",        "InputAttachment", "Matrix",
                                                     "Sampled1D",         "SampledBuffer",   "Shader"};
    for (const std::string& capability : edited.capabilities)
        if (!std::binary_search(built.capabilities.begin(), built.capabilities.end(), capability) &&
            std::find(kAlways.begin(), kAlways.end(), capability) == kAlways.end())
            return "it needs the " + capability +
                   " capability, which the shader its pipeline was made for does not (the device may not "
                   "have the feature, and this program does not enable it)";
    for (const auto& [slot, variables] : edited.descriptors) {
        std::string where = "set " + std::to_string(slot.first) + " binding " + std::to_string(slot.second);
        auto old = built.descriptors.find(slot);
        for (const Descriptor& d : variables) {
            std::string what = d.kind + " " + (d.block ? d.block->name : d.name);
            if (old == built.descriptors.end())
                return "it uses " + where + " (" + what +
                       "), which the shader its pipeline was made for does not declare";
            // The build's variable of the same kind and type at that slot (GLSL allows several).
            const std::vector<Descriptor>& candidates = old->second;
            auto same = std::find_if(candidates.begin(), candidates.end(), [&](const Descriptor& b) {
                return b.kind == d.kind && b.type == d.type;
            });
            if (same == candidates.end()) {
                const Descriptor& b = candidates.front();
                std::string theirs = b.type.empty() ? b.kind : b.kind + " (" + b.type + ")";
                std::string ours = d.type.empty() ? d.kind : d.kind + " (" + d.type + ")";
                if (b.kind == d.kind)
                    return where + " (" + d.name + ") is " + withArticle(d.type) +
                           " now; the shader its pipeline was made for has " + withArticle(b.type);
                return where + " (" + d.name + ") is " + withArticle(ours) +
                       " now; the shader its pipeline was made for has " + withArticle(theirs);
            }
            const Descriptor& b = *same;
            if (d.kind == "input attachment" && b.inputIndex != d.inputIndex)
                return where + " (" + d.name + ") reads input attachment " + std::to_string(d.inputIndex) +
                       " now; the shader its pipeline was made for reads " + std::to_string(b.inputIndex);
            if (!d.countConstant.empty() || !b.countConstant.empty()) {
                if (d.countConstant != b.countConstant || d.count != b.count)
                    return where + " (" + d.name + ") is an array sized by " +
                           (d.countConstant.empty() ? "a number"
                                                    : "specialization constant " + d.countConstant) +
                           " now; the shader its pipeline was made for sizes it by " +
                           (b.countConstant.empty() ? "a number"
                                                    : "specialization constant " + b.countConstant);
            } else if ((d.count == 0) != (b.count == 0) || d.count > b.count) {
                return where + " (" + d.name + ") is an array of " +
                       (d.count == 0 ? std::string("unknown length") : std::to_string(d.count)) +
                       " now; the shader its pipeline was made for declares " +
                       (b.count == 0 ? std::string("a runtime array") : std::to_string(b.count));
            }
            if (d.writable && !b.writable)
                return where + " (" + what +
                       ") is written now; the shader its pipeline was made for only reads it (readonly)";
            if (d.block && b.block)
                if (std::string change = blockChange(where + " (" + what + ")", *b.block, *d.block);
                    !change.empty())
                    return change;
        }
    }
    if (edited.pushConstants && !edited.pushConstants->used.empty()) {
        if (!built.pushConstants)
            return "it uses push constants; the shader its pipeline was made for has none";
        if (std::string change = blockChange("push constants (" + edited.pushConstants->name + ")",
                                             *built.pushConstants, *edited.pushConstants);
            !change.empty())
            return change;
    }
    for (const auto& [location, v] : edited.inputs) {
        auto old = built.inputs.find(location);
        if (old == built.inputs.end())
            return "it reads input location " + std::to_string(location) + " (" + v.name + ", " + v.type +
                   "), which the shader its pipeline was made for does not declare";
        if (old->second.type != v.type)
            return "input location " + std::to_string(location) + " (" + v.name + ") is " + v.type +
                   " now; the shader its pipeline was made for reads " + old->second.type;
    }
    for (const auto& [location, v] : built.outputs) {
        auto now = edited.outputs.find(location);
        if (now == edited.outputs.end())
            return "it no longer writes output location " + std::to_string(location) + " (" + v.name + ", " +
                   v.type + ")";
        if (now->second.type != v.type)
            return "output location " + std::to_string(location) + " (" + v.name + ") is " +
                   now->second.type + " now; the shader its pipeline was made for writes " + v.type;
    }
    // A new output has no reader: the next stage's inputs, or the attachments, are the build's.
    // Refused whatever the save order of a two-stage edit: a vertex shader saved before its
    // fragment shader must not go live alone (the validation layer warns of an output no stage
    // consumes).
    for (const auto& [location, v] : edited.outputs)
        if (!built.outputs.count(location))
            return "it writes output location " + std::to_string(location) + " (" + v.name + ", " + v.type +
                   "), which the shader its pipeline was made for does not declare";
    // The C++ sets a constant with the bytes of the build's type: a bool (VkBool32), int or uint
    // read as any of the three means the same number; a float or a wider type does not.
    auto kindOf = [](const std::string& type) {
        return type == "bool" || type == "int" || type == "uint" ? std::string("32-bit integer") : type;
    };
    for (const auto& [id, c] : edited.constants) {
        auto old = built.constants.find(id);
        if (old != built.constants.end() && kindOf(old->second.type) != kindOf(c.type))
            return "specialization constant " + std::to_string(id) + " (" + c.name + ") is " + c.type +
                   " now; the C++ sets it as " + old->second.type;
    }
    if (built.localSize != edited.localSize)
        return "local size is " + edited.localSize + " now; the dispatch is sized for " + built.localSize;
    return {};
}

}  // namespace

std::string shaderInterfaceChange(const std::vector<uint32_t>& built, const std::vector<uint32_t>& edited) {
    Reflection before(built), after(edited);
    Interface b = before.reflect(false), e = after.reflect(true);
    b.capabilities = capabilities(built);
    e.capabilities = capabilities(edited);
    return interfaceChange(b, e);
}

std::string specializationMismatch(const std::vector<uint32_t>& spirv,
                                   const VkSpecializationInfo& specialization) {
    Reflection reflection(spirv);
    std::map<unsigned, uint32_t> sizes;  // constant_id -> bytes of its value
    reflection.constantSizes(sizes);
    for (uint32_t i = 0; i < specialization.mapEntryCount; ++i) {
        const VkSpecializationMapEntry& entry = specialization.pMapEntries[i];
        auto found = sizes.find(entry.constantID);
        if (found == sizes.end())
            return "the pipeline sets specialization constant " + std::to_string(entry.constantID) +
                   ", which the shader does not declare";
        if (found->second != entry.size)
            return "the pipeline sets specialization constant " + std::to_string(entry.constantID) +
                   " with " + std::to_string(entry.size) + " bytes; the shader's is " +
                   std::to_string(found->second);
    }
    return {};
}

#else

std::string shaderInterfaceChange(const std::vector<uint32_t>&, const std::vector<uint32_t>&) {
    return {};
}

std::string specializationMismatch(const std::vector<uint32_t>&, const VkSpecializationInfo&) {
    return {};
}

#endif

}  // namespace common
