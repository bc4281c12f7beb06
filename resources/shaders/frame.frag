#version 330 core
// Shows the deep frame: exposure + tone operator + sRGB on the HDR texture (or a ready
// debug image), and an outline where the id differs from a neighbour and one is selected.
// toneMap and srgb are render/image/tonemap.cpp's, constant for constant:
// tests/unit/frame_shader_tonemap_test.cpp reads them here and fails when the two differ.
in vec2 uv;
out vec4 fragColor;
uniform sampler2D colorTex;
uniform usampler2D idTex;
uniform int displayReady;   // 1: colorTex already holds display values
uniform int tonemap;        // a ToneMap value; TONEMAP_* are defined by the program that loads this
uniform float exposure;
uniform uint selected[32];  // kMaxOutlined (ui/display/display_frame.h)
uniform int selectedCount;
uniform vec3 outlineColor;

bool isSelected(uint id) {
    for (int i = 0; i < selectedCount; ++i)
        if (selected[i] == id) return true;
    return false;
}

float sanitize(float x) { return x > 0.0 ? min(x, 1.0e4) : 0.0; }
float aces(float x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
vec3 toneMap(vec3 hdr) {
    float gain = exp2(exposure);
    vec3 x = vec3(sanitize(hdr.r * gain), sanitize(hdr.g * gain), sanitize(hdr.b * gain));
    if (tonemap == TONEMAP_LINEAR) return clamp(x / 4.0, 0.0, 1.0);
    if (tonemap == TONEMAP_REINHARD) {
        float lum = dot(x, vec3(0.2126, 0.7152, 0.0722));
        if (lum <= 0.0) return vec3(0.0);
        return clamp(x * ((lum / (1.0 + lum)) / lum), 0.0, 1.0);
    }
    if (tonemap == TONEMAP_ACES) return vec3(aces(x.r), aces(x.g), aces(x.b));
    return clamp(x, 0.0, 1.0);
}
float srgb(float c) {
    c = clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

void main() {
    ivec2 size = textureSize(colorTex, 0);
    ivec2 p = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
    // Ids are uploaded only while something is selected: read them only then.
    if (selectedCount > 0) {
        uint id = texelFetch(idTex, p, 0).r;
        ivec2 offs[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
        for (int k = 0; k < 4; ++k) {
            ivec2 q = p + offs[k];
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            uint n = texelFetch(idTex, q, 0).r;
            if (n != id && (isSelected(n) || isSelected(id))) {
                fragColor = vec4(outlineColor, 1.0);
                return;
            }
        }
    }
    vec3 c = texelFetch(colorTex, p, 0).rgb;
    if (displayReady == 0) {
        vec3 d = toneMap(c);
        c = vec3(srgb(d.r), srgb(d.g), srgb(d.b));
    }
    fragColor = vec4(c, 1.0);
}
