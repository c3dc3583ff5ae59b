"""three.js itself, release 111 (Debian's ``libjs-three``), rendering a ``MeshPhongMaterial``
plane in headless Chromium (WebGL 2 on SwiftShader) into a float32 render target, and the world
point every pixel shaded, so that `glshade.shade` can be held to each pixel.

The plane's normal is the same at every vertex, so the fragment normal is that normal
(normalised). The fragment's position is read back from a second draw of the same triangles
that writes the interpolated world position: the same barycentrics as the first draw's
``vViewPosition``. (Computing it from the pixel's centre instead would count the rasteriser's
sub-pixel snapping of the vertices, up to 1/32 of a pixel, 4·10⁻³ here, as a shading error.)
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np

import glshade as gs

THREE = Path("/usr/share/javascript/three/three.min.js")
# WebGL 2 without a GPU: Chromium's SwiftShader, on the CPU.
ARGUMENTS = (
    "--enable-unsafe-swiftshader",
    "--use-angle=swiftshader",
    "--allow-file-access-from-files",
)

PAGE = """<!doctype html><html><body>
<script src="%(three)s"></script>
<script>
window.renderPhong = function (c) {
  var canvas = document.createElement('canvas');
  var renderer = new THREE.WebGLRenderer({canvas: canvas, context: canvas.getContext('webgl2')});
  renderer.physicallyCorrectLights = c.physical;
  renderer.setClearColor(0x000000, 0);
  var target = new THREE.WebGLRenderTarget(c.width, c.height, {type: THREE.FloatType,
    format: THREE.RGBAFormat, minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter});
  var scene = new THREE.Scene();
  var rgb = function (a) { return new THREE.Color().setRGB(a[0], a[1], a[2]); };
  var v3 = function (a) { return new THREE.Vector3().fromArray(a); };
  var sides = {front: THREE.FrontSide, back: THREE.BackSide, double: THREE.DoubleSide};
  var m = c.material;
  var material = new THREE.MeshPhongMaterial({color: rgb(m.color), specular: rgb(m.specular),
    shininess: m.shininess, emissive: rgb(m.emissive), emissiveIntensity: m.emissive_intensity,
    opacity: m.opacity, side: sides[m.side]});
  var mesh = new THREE.Mesh(new THREE.PlaneBufferGeometry(60, 60, 60, 60), material);
  mesh.position.copy(v3(c.plane.center));
  mesh.lookAt(v3(c.plane.center).add(v3(c.plane.normal)));  // +z, the plane's normal
  scene.add(mesh);
  c.lights.forEach(function (l) {
    var light;
    if (l.type === 'AmbientLight') light = new THREE.AmbientLight(rgb(l.color), l.intensity);
    else if (l.type === 'HemisphereLight')
      light = new THREE.HemisphereLight(rgb(l.sky_color), rgb(l.ground_color), l.intensity);
    else if (l.type === 'DirectionalLight')
      light = new THREE.DirectionalLight(rgb(l.color), l.intensity);
    else if (l.type === 'PointLight')
      light = new THREE.PointLight(rgb(l.color), l.intensity, l.distance, l.decay);
    else light = new THREE.SpotLight(rgb(l.color), l.intensity, l.distance, l.angle, l.penumbra,
      l.decay);
    if (l.position) light.position.copy(v3(l.position));
    if (light.target) { light.target.position.copy(v3(l.target)); scene.add(light.target); }
    scene.add(light);
  });
  var k = c.camera, camera;
  if (k.kind === 'perspective')
    camera = new THREE.PerspectiveCamera(k.fov, c.width / c.height, k.near, k.far);
  else camera = new THREE.OrthographicCamera(-k.half_width, k.half_width, k.half_height,
    -k.half_height, k.near, k.far);
  camera.position.copy(v3(k.eye));
  camera.up.copy(v3(k.up));
  camera.lookAt(v3(k.target));
  var draw = function () {
    renderer.setRenderTarget(target);
    renderer.render(scene, camera);
    var pixels = new Float32Array(c.width * c.height * 4);
    renderer.readRenderTargetPixels(target, 0, 0, c.width, c.height, pixels);
    return Array.from(pixels);
  };
  var colours = draw();
  // The same triangles again, writing the world point each pixel interpolates: the same
  // barycentrics as MeshPhongMaterial's vViewPosition.
  mesh.material = new THREE.ShaderMaterial({side: sides[m.side],
    vertexShader: 'varying vec3 w; void main() { vec4 p = modelMatrix * vec4(position, 1.0);' +
      ' w = p.xyz; gl_Position = projectionMatrix * viewMatrix * p; }',
    fragmentShader: 'varying vec3 w; void main() { gl_FragColor = vec4(w, 1.0); }'});
  var points = draw();
  renderer.dispose();
  target.dispose();
  return {revision: THREE.REVISION, webgl2: renderer.capabilities.isWebGL2, colours: colours,
    points: points};
};
</script></body></html>
"""


def page(folder: Path) -> Path:
    """Writes the page that defines ``renderPhong`` into `folder`; returns its path."""
    path = folder / "threejs.html"
    path.write_text(PAGE % {"three": THREE.as_uri()}, encoding="utf-8")
    return path


def light_record(light: gs.threejs.Light) -> dict[str, Any]:
    """A `glshade.threejs` light as the page's light: its type and fields."""
    record: dict[str, Any] = {"type": type(light).__name__}
    for name, value in vars(light).items():
        record[name] = list(value) if isinstance(value, tuple) else value
    return record


def render(driver: Any, url: str, config: dict[str, Any]) -> tuple[np.ndarray, np.ndarray]:
    """three.js' float32 RGBA of `config` (see ``PAGE``) and the world point each pixel
    shaded, (height·width, 4) and (height·width, 3), bottom row first; points of pixels the
    plane does not cover are NaN."""
    if driver.current_url != url:
        driver.get(url)
    result = driver.execute_script(f"return window.renderPhong({json.dumps(config)});")
    assert result["revision"] == "111" and result["webgl2"], result
    colours = np.asarray(result["colours"], np.float64).reshape(-1, 4)
    points = np.asarray(result["points"], np.float64).reshape(-1, 4)
    # The clear colour's alpha 0 marks the pixels no triangle covered.
    return colours, np.where(points[:, 3:] == 1, points[:, :3], np.nan)
