#include "viewer/renderer/shader_program.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <stdexcept>
#include <string>

namespace tumble::viewer {
namespace {

GlObject compile(const char* name, GLenum stage, const char* source)
{
    GlObject shader(GlKind::Shader, glCreateShader(stage));
    glShaderSource(shader.name(), 1, &source, nullptr);
    glCompileShader(shader.name());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.name(), GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        char log[2048] = {};
        glGetShaderInfoLog(shader.name(), sizeof log, nullptr, log);
        throw std::runtime_error(std::string("shader ") + name +
                                 (stage == GL_VERTEX_SHADER ? " (vertex)" : " (fragment)") +
                                 " does not compile: " + log);
    }
    return shader;
}

} // namespace

ShaderProgram::ShaderProgram(const char* name, const char* vertexSource,
                             const char* fragmentSource)
    : m_program(GlKind::Program, glCreateProgram())
{
    const GlObject vertex = compile(name, GL_VERTEX_SHADER, vertexSource);
    const GlObject fragment = compile(name, GL_FRAGMENT_SHADER, fragmentSource);
    glAttachShader(m_program.name(), vertex.name());
    glAttachShader(m_program.name(), fragment.name());
    glLinkProgram(m_program.name());
    glDetachShader(m_program.name(), vertex.name());
    glDetachShader(m_program.name(), fragment.name());
    GLint ok = GL_FALSE;
    glGetProgramiv(m_program.name(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        char log[2048] = {};
        glGetProgramInfoLog(m_program.name(), sizeof log, nullptr, log);
        throw std::runtime_error(std::string("shader ") + name + " does not link: " + log);
    }
}

GLint ShaderProgram::location(const char* uniform) const
{
    return glGetUniformLocation(m_program.name(), uniform);
}

void ShaderProgram::set(const char* uniform, int value) const
{
    glUniform1i(location(uniform), value);
}

void ShaderProgram::set(const char* uniform, float value) const
{
    glUniform1f(location(uniform), value);
}

void ShaderProgram::set(const char* uniform, const glm::vec2& value) const
{
    glUniform2fv(location(uniform), 1, glm::value_ptr(value));
}

void ShaderProgram::set(const char* uniform, const glm::vec3& value) const
{
    glUniform3fv(location(uniform), 1, glm::value_ptr(value));
}

void ShaderProgram::set(const char* uniform, const glm::vec2* values, int count) const
{
    glUniform2fv(location(uniform), count, glm::value_ptr(*values));
}

void ShaderProgram::set(const char* uniform, const glm::mat3& value) const
{
    glUniformMatrix3fv(location(uniform), 1, GL_FALSE, glm::value_ptr(value));
}

void ShaderProgram::set(const char* uniform, const glm::mat4& value) const
{
    glUniformMatrix4fv(location(uniform), 1, GL_FALSE, glm::value_ptr(value));
}

} // namespace tumble::viewer
