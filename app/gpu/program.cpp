#include "gpu/program.hpp"

#include "gpu/gl_error.hpp"
#include "gpu/shader_library.hpp"

namespace steerseg::gpu {

std::string withDefines(std::string_view source, const Defines& defines) {
    std::string out(source);
    std::size_t insertAt = 0;
    if (out.rfind("#version", 0) == 0) {
        insertAt = out.find('\n');
        insertAt = insertAt == std::string::npos ? out.size() : insertAt + 1;
    }
    std::string block;
    for (const auto& [key, value] : defines) {
        block += "#define " + key + " " + value + "\n";
    }
    out.insert(insertAt, block);
    return out;
}

namespace {

std::string_view sourceOf(std::string_view name) {
    auto source = findShaderSource(name);
    if (!source) {
        throw GlError("shader \"" + std::string(name) + "\" is not embedded in this build");
    }
    return *source;
}

GLuint compileSource(GLenum stage, std::string_view name, std::string_view source,
                     const Defines& defines) {
    const std::string text = withDefines(source, defines);
    GLuint shader = glCreateShader(stage);
    const char* ptr = text.c_str();
    glShaderSource(shader, 1, &ptr, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        glDeleteShader(shader);
        throw GlError("shader " + std::string(name) + " failed to compile: " + log);
    }
    return shader;
}

GLuint compileStage(GLenum stage, std::string_view name, const Defines& defines) {
    return compileSource(stage, name, sourceOf(name), defines);
}

Program link(std::initializer_list<GLuint> shaders, std::string_view what) {
    Program program(glCreateProgram());
    for (GLuint s : shaders) {
        glAttachShader(program.id(), s);
    }
    glLinkProgram(program.id());
    for (GLuint s : shaders) {
        glDetachShader(program.id(), s);
        glDeleteShader(s);
    }
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program.id(), length, nullptr, log.data());
        throw GlError("program " + std::string(what) + " failed to link: " + log);
    }
    return program;
}

} // namespace

Program buildComputeProgram(std::string_view name, const Defines& defines) {
    return link({compileStage(GL_COMPUTE_SHADER, name, defines)}, name);
}

Program buildComputeProgramFromSource(std::string_view label, std::string_view source,
                                      const Defines& defines) {
    return link({compileSource(GL_COMPUTE_SHADER, label, source, defines)}, label);
}

Program buildGraphicsProgram(std::string_view vertexName, std::string_view fragmentName,
                             const Defines& defines) {
    GLuint vs = compileStage(GL_VERTEX_SHADER, vertexName, defines);
    GLuint fs = 0;
    try {
        fs = compileStage(GL_FRAGMENT_SHADER, fragmentName, defines);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    return link({vs, fs}, std::string(vertexName) + " + " + std::string(fragmentName));
}

} // namespace steerseg::gpu
