// ShaderProgram: compiles and links a GLSL 330 vertex and fragment shader pair and sets its
// uniforms by name.
#pragma once

#include "viewer/renderer/gl_object.hpp"

#include <glm/glm.hpp>

namespace tumble::viewer {

class ShaderProgram {
public:
    /// Throws std::runtime_error with the compiler's log when a stage does not compile or link.
    ShaderProgram(const char* name, const char* vertexSource, const char* fragmentSource);

    void use() const { glUseProgram(m_program.name()); }
    void set(const char* uniform, int value) const;
    void set(const char* uniform, float value) const;
    void set(const char* uniform, const glm::vec2& value) const;
    void set(const char* uniform, const glm::vec3& value) const;
    void set(const char* uniform, const glm::mat3& value) const;
    void set(const char* uniform, const glm::mat4& value) const;
    /// An array uniform: `count` vec2 from `values`.
    void set(const char* uniform, const glm::vec2* values, int count) const;

private:
    [[nodiscard]] GLint location(const char* uniform) const;

    GlObject m_program;
};

} // namespace tumble::viewer
