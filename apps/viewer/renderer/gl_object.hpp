// GlObject: owns one OpenGL object name (buffer, vertex array, texture, framebuffer,
// renderbuffer, shader or program) and deletes it with the matching call.
#pragma once

#include "viewer/renderer/gl.hpp"

namespace tumble::viewer {

enum class GlKind { Buffer, VertexArray, Texture, Framebuffer, Renderbuffer, Shader, Program };

class GlObject {
public:
    GlObject() = default;
    GlObject(GlKind kind, GLuint name) : m_kind(kind), m_name(name) {}
    /// Generates a new object of `kind` (not for shaders and programs, which need a type).
    static GlObject create(GlKind kind);
    ~GlObject() { release(); }

    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;
    GlObject(GlObject&& other) noexcept : m_kind(other.m_kind), m_name(other.m_name)
    {
        other.m_name = 0;
    }
    GlObject& operator=(GlObject&& other) noexcept;

    [[nodiscard]] GLuint name() const { return m_name; }

private:
    void release();

    GlKind m_kind = GlKind::Buffer;
    GLuint m_name = 0;
};

} // namespace tumble::viewer
