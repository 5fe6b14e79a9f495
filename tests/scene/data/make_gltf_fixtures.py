# Writes scene.gltf (buffer and PNG image as data: URIs) and scene.glb, the glTF fixtures of
# gltf_import_test.cpp. Run from tests/scene/data/ after changing it.
import base64, json, struct, zlib
def png(w, h, rows):
    raw = b''.join(b'\x00' + bytes(r) for r in rows)
    def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    return b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)) + chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b'')
image = png(2, 1, [[255, 0, 0, 0, 255, 0]])
pos = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]
buf = b''.join(struct.pack('<3f', *p) for p in pos)                      # 0..48
buf += b''.join(struct.pack('<2f', *uv) for uv in [(0, 1), (1, 1), (1, 0), (0, 0)])  # 48..80
buf += struct.pack('<6H', 0, 1, 2, 0, 2, 3)                             # 80..92
buf += bytes([0, 1, 2]) + bytes([0, 1, 7]) + b'\x00\x00'                # 92..95, 95..98, pad to 100
buf += b''.join(struct.pack('<3f', 0, 0, 1) for _ in range(3))          # 100..136
assert len(buf) == 136
views = [(0, 48), (48, 32), (80, 12), (92, 3), (100, 36), (95, 3)]
def gltf(buffer_entry):
    acc = [
        '{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 0]}',
        '{"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"}',
        '{"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}',
        '{"bufferView": 3, "componentType": 5121, "count": 3, "type": "SCALAR"}',
        '{"bufferView": 4, "componentType": 5126, "count": 3, "type": "VEC3"}',
        '{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 0]}',
        '{"bufferView": 5, "componentType": 5121, "count": 3, "type": "SCALAR"}',
    ]
    bv = ',\n    '.join('{"buffer": 0, "byteOffset": %d, "byteLength": %d}' % v for v in views)
    return '''{
  "asset": {"version": "2.0", "generator": "written for lumagraph tests"},
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [
    {"type": "directional", "color": [1.0, 0.9, 0.8], "intensity": 2.0},
    {"type": "point", "intensity": 5.0, "range": 10.0}
  ]}},
  "scene": 0,
  "scenes": [{"nodes": [0, 3, 4, 5]}],
  "nodes": [
    {"name": "root", "translation": [1, 2, 3], "children": [1, 2]},
    {"name": "quad node", "mesh": 0, "scale": [2, 2, 2], "rotation": [0, 0.70710678, 0, 0.70710678]},
    {"name": "tri node", "mesh": 1, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 1]},
    {"name": "camera node", "camera": 0, "translation": [0, 1, 5]},
    {"name": "sun", "rotation": [-0.38268343, 0, 0, 0.92387953], "extensions": {"KHR_lights_punctual": {"light": 0}}},
    {"name": "lamp", "translation": [0, 3, 0], "extensions": {"KHR_lights_punctual": {"light": 1}}}
  ],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.6, "znear": 0.1, "aspectRatio": 1.5}}],
  "meshes": [
    {"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]},
    {"name": "tri", "primitives": [{"attributes": {"POSITION": 5, "NORMAL": 4}, "indices": 3}]}
  ],
  "materials": [{"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.25, 1], "metallicFactor": 0.5,
                 "roughnessFactor": 0.25, "baseColorTexture": {"index": 0}}, "emissiveFactor": [0.1, 0.2, 0.3]}],
  "textures": [{"source": 0}],
  "images": [{"uri": "data:image/png;base64,%s"}],
  "buffers": [%s],
  "bufferViews": [
    %s
  ],
  "accessors": [
    %s
  ]
}
''' % (base64.b64encode(image).decode(), buffer_entry, bv, ',\n    '.join(acc))
text = gltf('{"byteLength": 136, "uri": "data:application/octet-stream;base64,%s"}' % base64.b64encode(buf).decode())
json.loads(text)
open('scene.gltf', 'w').write(text)
j = gltf('{"byteLength": 136}').encode()
j += b' ' * ((4 - len(j) % 4) % 4)
glb = b'glTF' + struct.pack('<II', 2, 12 + 8 + len(j) + 8 + len(buf)) + struct.pack('<I', len(j)) + b'JSON' + j + struct.pack('<I', len(buf)) + b'BIN\x00' + buf
open('scene.glb', 'wb').write(glb)
