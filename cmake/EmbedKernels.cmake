# Run at build time: writes OUTPUT, a C++ file defining vf::sim::opencl::kernelSource(name) over the
# OpenCL C files in SOURCES (a |-separated list), each embedded as a raw string literal.
string(REPLACE "|" ";" SOURCES "${SOURCES}")
set(body "")
set(table "")
set(everything "")
foreach(file IN LISTS SOURCES)
  get_filename_component(name "${file}" NAME)
  file(READ "${file}" text)
  string(APPEND everything "${name}\n${text}")
  string(MAKE_C_IDENTIFIER "${name}" id)
  string(APPEND body "const char ${id}[] = R\"vfcl(${text})vfcl\";\n")
  string(APPEND table "    {\"${name}\", ${id}},\n")
endforeach()
string(SHA1 digest "${everything}")
file(WRITE "${OUTPUT}.tmp" "// Generated from the .cl files beside the OpenCL host code. Do not edit.
#include \"sim/opencl/KernelSources.h\"

#include <map>
#include <stdexcept>

namespace vf::sim::opencl {
namespace {
${body}} // namespace

std::string_view kernelSource(std::string_view name)
{
    static const std::map<std::string_view, std::string_view> sources{
${table}    };
    const auto it = sources.find(name);
    return it == sources.end() ? std::string_view() : it->second;
}

std::string joinedKernelSources(std::initializer_list<std::string_view> names)
{
    std::string joined;
    for (std::string_view name : names) {
        const std::string_view text = kernelSource(name);
        if (text.empty())
            throw std::logic_error(\"no embedded OpenCL kernel file \" + std::string(name));
        joined.append(text).append(\"\\n\");
    }
    return joined;
}

std::string_view kernelSourcesDigest()
{
    return \"${digest}\";
}

} // namespace vf::sim::opencl
")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUTPUT}.tmp" "${OUTPUT}")
file(REMOVE "${OUTPUT}.tmp")
