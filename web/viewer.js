// gab's progressive viewer: streams a .gab file, decodes it in WebAssembly
// (gab_web.js, web/gab_web.cpp) each time another chunk has completely
// arrived, and draws the shape with WebGL. Hand-written, no libraries.
//
// URL parameters:
//   file=NAME.gab   the file to show (a URL relative to this page)
//   level=L         stop at level L (the first L + 1 chunks), as if the
//                   file ended there
//   compact=1       a one-line panel (level, anchors, bytes), for pictures
//   flat=1          flat shading: one normal per triangle (facets visible)
//   zoom=Z          the first view's distance over the fitting one (0.5: twice
//                   as close), for close-ups
//   up=AXIS         the file's axis shown up: x, y, z, -x, -y or -z (default
//                   +Y, or +Z when the view is along Y; the U key cycles)
//
// For scripts: once the last level is shown, document.title is
// "gab: done n=<vertices> anchors=<anchors>"; on a bad file (decoder or HTTP
// error) it is "gab: error: <message>". Every level shown is a list item
// with data-level, data-anchors, data-bytes, data-total and data-decode-ms;
// the canvas's data-view is the first view, {"toCamera": [x, y, z], "up": AXIS}.
'use strict';

(function () {
  const params = new URLSearchParams(window.location.search);
  const fileName = params.get('file');
  const stopLevel = params.has('level') ? parseInt(params.get('level'), 10) : -1;
  const compact = params.get('compact') === '1';
  const flatShading = params.get('flat') === '1';
  const homeZoom = params.has('zoom') ? Math.min(20, Math.max(0.05, parseFloat(params.get('zoom')) || 1)) : 1;
  if (compact) document.body.classList.add('compact');

  const canvas = document.getElementById('view');
  const statusEl = document.getElementById('status');
  const errorEl = document.getElementById('error');
  const levelsEl = document.getElementById('levels');
  const startTime = performance.now();

  // ---- page state --------------------------------------------------------

  let gab = null;          // the WebAssembly module
  let received = 0;        // bytes in the module's buffer
  let total = 0;           // Content-Length (0: unknown)
  let streamDone = false;
  let decodedChunks = 0;   // complete chunks of the level on screen
  let shown = null;        // what the decoder said of it
  let stepPending = false;
  let finished = false;    // done or failed: nothing more happens

  function kb(bytes) { return (bytes / 1024).toFixed(1) + ' KB'; }

  function fail(message) {
    if (finished) return;
    finished = true;
    document.title = 'gab: error: ' + message;
    errorEl.textContent = 'error: ' + message;
  }

  // ---- streaming ---------------------------------------------------------

  // Copies `bytes` after the ones received so far, growing the module's buffer.
  function append(bytes) {
    const need = received + bytes.length;
    const capacity = Math.max(need, total, 2 * received);
    const ptr = gab._gab_web_buffer(capacity);
    if (!ptr) throw new Error('out of memory for ' + need + ' bytes');
    gab.HEAPU8.set(bytes, ptr + received);  // HEAPU8 afresh: the memory may have grown
    received = need;
  }

  // Decoding waits for a task of its own, so bytes that are already here
  // are appended first, and a level overtaken while another decoded is skipped.
  function schedule() {
    if (stepPending || finished) return;
    stepPending = true;
    setTimeout(step, 0);
  }

  function step() {
    stepPending = false;
    if (finished) return;
    let frames = gab._gab_web_frames(received);
    if (frames === -2) return fail(gab.UTF8ToString(gab._gab_web_message()));
    let last = streamDone;
    if (stopLevel >= 0 && frames > stopLevel) {
      frames = stopLevel + 1;
      last = true;
    }
    if (frames < 0) frames = 0;
    if (frames > decodedChunks || (last && shown === null)) {
      // Whole chunks only; the decoder checks every checksum.
      const size = frames > 0 ? gab._gab_web_chunk_end(frames - 1) : received;
      if (!decodeAndShow(size)) return;
    }
    if (shown && (last || isComplete(shown))) conclude(shown);
  }

  function isComplete(info) {
    return info.chunks === info.chunksInFile && info.anchors === info.anchorsInFile;
  }

  // The last level is on screen: done, or the file ended early.
  function conclude(info) {
    if (isComplete(info) || stopLevel >= 0) {
      finished = true;
      document.title = 'gab: done n=' + info.n + ' anchors=' + info.anchors;
    } else {
      fail('the file ends inside chunk ' + info.chunks + ' of ' + info.chunksInFile +
           ' (showing the first ' + info.chunks + ')');
    }
  }

  // Decodes the first `size` bytes and shows the shape; false on an error.
  function decodeAndShow(size) {
    const t0 = performance.now();
    let rc;
    try {
      rc = gab._gab_web_decode(size, -1);
    } catch (e) {
      fail('the decoder stopped: ' + e);
      return false;
    }
    const decodeMs = performance.now() - t0;
    if (rc !== 0) {
      fail(gab.UTF8ToString(gab._gab_web_message()));
      return false;
    }
    const info = {
      n: gab._gab_web_vertices(),
      t: gab._gab_web_triangles(),
      anchors: gab._gab_web_anchors(),
      anchorsInFile: gab._gab_web_anchors_in_file(),
      chunks: gab._gab_web_chunks(),
      chunksInFile: gab._gab_web_chunks_in_file(),
      refined: gab._gab_web_refined() !== 0,
      detail: gab._gab_web_detail() !== 0,
      decodeMs: decodeMs,
    };
    decodedChunks = info.chunks;
    shown = info;
    const positions = new Float32Array(gab.HEAPF32.buffer, gab._gab_web_positions(), 3 * info.n).slice();
    const indices = new Uint32Array(gab.HEAPU32.buffer, gab._gab_web_indices(), 3 * info.t).slice();
    uploadMesh(positions, indices);
    report(info, size);
    draw();
    return true;
  }

  function report(info, size) {
    const level = info.chunks - 1;
    let kind = '';
    if (info.detail) kind = ' (detail)';
    else if (info.refined) kind = ' (refinement)';
    const ms = info.decodeMs.toFixed(0);
    statusEl.textContent =
      'level ' + level + kind + ' of ' + (info.chunksInFile - 1) +
      ' · anchors ' + info.anchors + ' / ' + info.anchorsInFile +
      ' · ' + kb(size) + (total ? ' / ' + kb(total) : '') +
      (compact ? '' : ' · n = ' + info.n + ', ' + info.t + ' triangles · decoded in ' + ms + ' ms');
    const item = document.createElement('li');
    item.className = 'level';
    item.dataset.level = String(level);
    item.dataset.anchors = String(info.anchors);
    item.dataset.bytes = String(size);
    item.dataset.total = String(total);
    item.dataset.decodeMs = ms;
    item.textContent = 'level ' + level + kind + ': ' + info.anchors + ' anchors' + ' at ' + kb(size) + ', decoded in ' + ms +
      ' ms, shown at ' + (performance.now() - startTime).toFixed(0) + ' ms';
    levelsEl.appendChild(item);
  }

  async function load() {
    if (!fileName) return fail('no file given: open index.html?file=NAME.gab');
    document.getElementById('name').textContent = fileName;
    if (typeof createGabModule !== 'function') return fail('gab_web.js did not load');
    try {
      gab = await createGabModule();
    } catch (e) {
      return fail('the decoder did not load: ' + e);
    }
    statusEl.textContent = 'fetching ' + fileName + '…';
    let response;
    try {
      response = await fetch(fileName);
    } catch (e) {
      return fail('cannot fetch ' + fileName + ': ' + e.message);
    }
    if (!response.ok) return fail('HTTP ' + response.status + ' ' + response.statusText + ' for ' + fileName);
    total = Number(response.headers.get('Content-Length')) || 0;
    const reader = response.body.getReader();
    for (;;) {
      let chunk;
      try {
        chunk = await reader.read();
      } catch (e) {
        return fail('reading ' + fileName + ': ' + e.message);
      }
      if (chunk.done) break;
      if (finished) {
        reader.cancel();
        return;
      }
      append(chunk.value);
      schedule();
    }
    streamDone = true;
    if (received === 0) return fail(fileName + ' is empty');
    schedule();
  }

  // ---- WebGL -------------------------------------------------------------

  const gl = canvas.getContext('webgl2', { antialias: true, preserveDrawingBuffer: true }) ||
             canvas.getContext('webgl', { antialias: true, preserveDrawingBuffer: true });
  const isWebGL2 = typeof WebGL2RenderingContext !== 'undefined' && gl instanceof WebGL2RenderingContext;
  let program = null, positionBuffer = null, normalBuffer = null, indexBuffer = null;
  let indexCount = 0;
  let center = [0, 0, 0], radius = 1, fitted = false;

  const vertexSource = `
    attribute vec3 position;
    attribute vec3 normal;
    uniform mat4 modelView;
    uniform mat4 projection;
    varying vec3 viewNormal;
    varying vec3 viewPosition;
    void main() {
      vec4 p = modelView * vec4(position, 1.0);
      viewPosition = p.xyz;
      viewNormal = mat3(modelView) * normal;  // rotation and uniform scale only
      gl_Position = projection * p;
    }`;
  const fragmentSource = `
    precision mediump float;
    varying vec3 viewNormal;
    varying vec3 viewPosition;
    void main() {
      vec3 n = normalize(viewNormal);
      vec3 v = normalize(-viewPosition);
      if (dot(n, v) < 0.0) n = -n;  // two-sided
      vec3 key = normalize(vec3(0.4, 0.7, 1.0));
      vec3 fill = normalize(vec3(-0.6, -0.2, 0.5));
      float diffuse = 0.70 * max(dot(n, key), 0.0) + 0.25 * max(dot(n, fill), 0.0);
      float specular = 0.25 * pow(max(dot(n, normalize(key + v)), 0.0), 40.0);
      vec3 base = vec3(0.80, 0.66, 0.50);
      gl_FragColor = vec4(base * (0.18 + diffuse) + vec3(specular), 1.0);
    }`;

  function compile(type, source) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(shader));
    return shader;
  }

  function initGL() {
    if (!gl) return 'WebGL is not available in this browser';
    if (!isWebGL2 && !gl.getExtension('OES_element_index_uint')) return 'WebGL lacks 32-bit indices';
    program = gl.createProgram();
    gl.attachShader(program, compile(gl.VERTEX_SHADER, vertexSource));
    gl.attachShader(program, compile(gl.FRAGMENT_SHADER, fragmentSource));
    gl.bindAttribLocation(program, 0, 'position');
    gl.bindAttribLocation(program, 1, 'normal');
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) return gl.getProgramInfoLog(program);
    positionBuffer = gl.createBuffer();
    normalBuffer = gl.createBuffer();
    indexBuffer = gl.createBuffer();
    gl.enable(gl.DEPTH_TEST);
    return '';
  }

  // Area-weighted vertex normals: the sum of the cross products of the
  // triangles around each vertex, normalized.
  function vertexNormals(positions, indices) {
    const normals = new Float32Array(positions.length);
    const p = positions;
    for (let i = 0; i < indices.length; i += 3) {
      const a = 3 * indices[i], b = 3 * indices[i + 1], c = 3 * indices[i + 2];
      const ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
      const vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
      const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
      for (const k of [a, b, c]) {
        normals[k] += nx;
        normals[k + 1] += ny;
        normals[k + 2] += nz;
      }
    }
    for (let k = 0; k < normals.length; k += 3) {
      const len = Math.hypot(normals[k], normals[k + 1], normals[k + 2]) || 1;
      normals[k] /= len;
      normals[k + 1] /= len;
      normals[k + 2] /= len;
    }
    return normals;
  }

  // Flat shading: every triangle its own three vertices, so the normals
  // averaged at a vertex are its triangle's (three times the memory).
  function unshared(positions, indices) {
    const flat = new Float32Array(3 * indices.length);
    for (let k = 0; k < indices.length; ++k) {
      for (let c = 0; c < 3; ++c) flat[3 * k + c] = positions[3 * indices[k] + c];
    }
    const order = new Uint32Array(indices.length);
    for (let k = 0; k < order.length; ++k) order[k] = k;
    return [flat, order];
  }

  // The first level fixes the camera (the bounding box barely moves after):
  // each later level replaces the shape in place, so refinement is visible.
  function uploadMesh(positions, indices) {
    if (!program) return;
    if (!fitted) {
      const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
      for (let i = 0; i < positions.length; i += 3) {
        for (let c = 0; c < 3; ++c) {
          lo[c] = Math.min(lo[c], positions[i + c]);
          hi[c] = Math.max(hi[c], positions[i + c]);
        }
      }
      if (positions.length === 0) { lo.fill(0); hi.fill(1); }
      center = [0, 1, 2].map((c) => 0.5 * (lo[c] + hi[c]));
      radius = 0.5 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1;
      axes = principalAxes(positions, indices);
      homeView();
      fitted = true;
    }
    if (flatShading) [positions, indices] = unshared(positions, indices);
    gl.bindBuffer(gl.ARRAY_BUFFER, positionBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, positions, gl.STATIC_DRAW);
    gl.bindBuffer(gl.ARRAY_BUFFER, normalBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, vertexNormals(positions, indices), gl.STATIC_DRAW);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, indexBuffer);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
    indexCount = indices.length;
  }

  // ---- camera: an orbit around the box's centre -------------------------

  // Column-major 4x4 matrices, as WebGL takes them.
  function multiply(a, b) {
    const out = new Float32Array(16);
    for (let col = 0; col < 4; ++col) {
      for (let row = 0; row < 4; ++row) {
        let s = 0;
        for (let k = 0; k < 4; ++k) s += a[k * 4 + row] * b[col * 4 + k];
        out[col * 4 + row] = s;
      }
    }
    return out;
  }

  function rotation(axis, angle) {  // about a unit axis
    const [x, y, z] = axis, c = Math.cos(angle), s = Math.sin(angle), t = 1 - c;
    return new Float32Array([
      t * x * x + c, t * x * y + s * z, t * x * z - s * y, 0,
      t * x * y - s * z, t * y * y + c, t * y * z + s * x, 0,
      t * x * z + s * y, t * y * z - s * x, t * z * z + c, 0,
      0, 0, 0, 1]);
  }

  function translation(x, y, z) {
    return new Float32Array([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, z, 1]);
  }

  const fov = 35 * Math.PI / 180;
  let orientation = multiply(rotation([1, 0, 0], 0.25), rotation([0, 1, 0], -0.45));
  let zoom = 1;  // distance over the fitting distance

  // ---- the first view: from the principal axes ---------------------------
  //
  // The camera looks along the surface's axis of least spread (the smallest
  // eigenvalue's eigenvector of its area-weighted covariance), so it sees
  // the widest silhouette: a horse from the side, a face from the front,
  // never a flat or long shape edge-on or from above. A file says nothing of
  // which way is up: the file's +Y is (OBJ's and glTF's convention), or +Z
  // where +Y is within 45 degrees of the view; `up=AXIS` in the URL (x, y, z,
  // -x, -y, -z) or the U key (the next axis) chooses another.

  // The surface's principal axes, the largest spread first: eigenvectors of
  // its covariance, each triangle's second moment taken exactly (area / 12 *
  // (aa' + bb' + cc' + ss'), s = a + b + c), so uneven sampling does not pull
  // them. Cyclic Jacobi rotations on the 3 x 3 matrix.
  function principalAxes(positions, indices) {
    let area = 0;
    const mean = [0, 0, 0], second = [0, 0, 0, 0, 0, 0];  // xx yy zz xy xz yz
    const a = [0, 0, 0], b = [0, 0, 0], c = [0, 0, 0], sum = [0, 0, 0];
    for (let k = 0; k + 2 < indices.length; k += 3) {
      for (let d = 0; d < 3; ++d) {
        a[d] = positions[3 * indices[k] + d] - center[d];
        b[d] = positions[3 * indices[k + 1] + d] - center[d];
        c[d] = positions[3 * indices[k + 2] + d] - center[d];
        sum[d] = a[d] + b[d] + c[d];
      }
      const ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
      const vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
      const w = 0.5 * Math.hypot(uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx);
      area += w;
      for (let d = 0; d < 3; ++d) mean[d] += w * sum[d] / 3;
      for (const p of [a, b, c, sum]) {
        second[0] += w / 12 * p[0] * p[0];
        second[1] += w / 12 * p[1] * p[1];
        second[2] += w / 12 * p[2] * p[2];
        second[3] += w / 12 * p[0] * p[1];
        second[4] += w / 12 * p[0] * p[2];
        second[5] += w / 12 * p[1] * p[2];
      }
    }
    if (!(area > 0)) return [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
    const m = mean.map((v) => v / area);
    const A = [
      [second[0] / area - m[0] * m[0], second[3] / area - m[0] * m[1], second[4] / area - m[0] * m[2]],
      [second[3] / area - m[0] * m[1], second[1] / area - m[1] * m[1], second[5] / area - m[1] * m[2]],
      [second[4] / area - m[0] * m[2], second[5] / area - m[1] * m[2], second[2] / area - m[2] * m[2]]];
    const V = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];  // columns: the eigenvectors
    for (let sweep = 0; sweep < 50; ++sweep) {
      const off = Math.abs(A[0][1]) + Math.abs(A[0][2]) + Math.abs(A[1][2]);
      if (off <= 1e-15 * (Math.abs(A[0][0]) + Math.abs(A[1][1]) + Math.abs(A[2][2]))) break;
      for (const [p, q] of [[0, 1], [0, 2], [1, 2]]) {
        if (A[p][q] === 0) continue;
        // The rotation that zeroes A[p][q] (Golub & Van Loan, the symmetric Schur decomposition).
        const theta = (A[q][q] - A[p][p]) / (2 * A[p][q]);
        const t = Math.sign(theta || 1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
        const cs = 1 / Math.sqrt(t * t + 1), sn = t * cs;
        for (let k = 0; k < 3; ++k) {  // A J
          const akp = A[k][p], akq = A[k][q];
          A[k][p] = cs * akp - sn * akq;
          A[k][q] = sn * akp + cs * akq;
        }
        for (let k = 0; k < 3; ++k) {  // J' A
          const apk = A[p][k], aqk = A[q][k];
          A[p][k] = cs * apk - sn * aqk;
          A[q][k] = sn * apk + cs * aqk;
        }
        for (let k = 0; k < 3; ++k) {
          const vkp = V[k][p], vkq = V[k][q];
          V[k][p] = cs * vkp - sn * vkq;
          V[k][q] = sn * vkp + cs * vkq;
        }
      }
    }
    return [0, 1, 2].sort((i, j) => A[j][j] - A[i][i]).map((i) => [V[0][i], V[1][i], V[2][i]]);
  }

  const upAxes = ['y', 'z', 'x', '-y', '-z', '-x'];
  function axisVector(name) {
    const v = [0, 0, 0];
    v['xyz'.indexOf(name[name.length - 1])] = name[0] === '-' ? -1 : 1;
    return v;
  }
  const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const cross = (u, v) => [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
  const unit = (v) => { const l = Math.hypot(v[0], v[1], v[2]) || 1; return v.map((x) => x / l); };

  let axes = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];  // principal, the largest spread first
  let upAxis = params.get('up');
  if (upAxis !== null && !upAxes.includes(upAxis)) {
    errorEl.textContent = 'up=' + upAxis + ' is not one of ' + upAxes.join(', ') + ': the default up is used';
    upAxis = null;
  }

  // The view along the thinnest axis with upAxis (or the default) up; zoom
  // fits the bounding sphere. The camera sits on the side of the axis that
  // faces the file's +X, +Y or +Z (whichever it is nearest), as an
  // unrotated view faces +Z. An up along the thinnest axis itself takes the
  // middle axis as the view instead.
  function homeView() {
    const up = upAxis !== null ? upAxis : Math.abs(axes[2][1]) > Math.SQRT1_2 ? 'z' : 'y';
    const upWorld = axisVector(up);
    let toCamera = Math.abs(dot(upWorld, axes[2])) > 0.99 ? axes[1].slice() : axes[2].slice();
    const size = toCamera.map(Math.abs);
    if (toCamera[size.indexOf(Math.max(...size))] < 0) toCamera = toCamera.map((x) => -x);
    const upVector = unit(upWorld.map((x, k) => x - dot(upWorld, toCamera) * toCamera[k]));
    const right = unit(cross(upVector, toCamera));
    // Rows right, up, toCamera: world to camera (which looks down its -Z).
    orientation = new Float32Array([
      right[0], upVector[0], toCamera[0], 0,
      right[1], upVector[1], toCamera[1], 0,
      right[2], upVector[2], toCamera[2], 0,
      0, 0, 0, 1]);
    zoom = homeZoom;
    canvas.dataset.view = JSON.stringify({ toCamera: toCamera.map((x) => +x.toFixed(4)), up: up });
  }

  function fitView() { homeView(); draw(); }

  function resize() {
    const ratio = window.devicePixelRatio || 1;
    const w = Math.max(1, Math.round(canvas.clientWidth * ratio));
    const h = Math.max(1, Math.round(canvas.clientHeight * ratio));
    if (canvas.width !== w || canvas.height !== h) {
      canvas.width = w;
      canvas.height = h;
    }
  }

  function draw() {
    if (!program) return;
    resize();
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(0.957, 0.957, 0.949, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    if (indexCount === 0) return;
    const aspect = canvas.width / canvas.height;
    // The bounding sphere fits the narrower of the two field-of-view angles.
    const half = aspect >= 1 ? fov / 2 : Math.atan(Math.tan(fov / 2) * aspect);
    const distance = zoom * radius / Math.sin(half) * 1.05;
    const near = Math.max(distance - 2 * radius, distance * 0.01), far = distance + 2 * radius;
    const f = 1 / Math.tan(fov / 2);
    const projection = new Float32Array([
      f / aspect, 0, 0, 0, 0, f, 0, 0,
      0, 0, (far + near) / (near - far), -1, 0, 0, 2 * far * near / (near - far), 0]);
    const modelView = multiply(translation(0, 0, -distance),
                               multiply(orientation, translation(-center[0], -center[1], -center[2])));
    gl.useProgram(program);
    gl.uniformMatrix4fv(gl.getUniformLocation(program, 'modelView'), false, modelView);
    gl.uniformMatrix4fv(gl.getUniformLocation(program, 'projection'), false, projection);
    gl.bindBuffer(gl.ARRAY_BUFFER, positionBuffer);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
    gl.bindBuffer(gl.ARRAY_BUFFER, normalBuffer);
    gl.enableVertexAttribArray(1);
    gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 0, 0);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, indexBuffer);
    gl.drawElements(gl.TRIANGLES, indexCount, gl.UNSIGNED_INT, 0);
  }

  let frameRequested = false;
  function redraw() {
    if (frameRequested) return;
    frameRequested = true;
    requestAnimationFrame(() => { frameRequested = false; draw(); });
  }

  // Dragging turns the shape about the screen axis perpendicular to the
  // drag (a trackball); two pointers pinch to zoom, as does the wheel.
  const pointers = new Map();
  let pinchDistance = 0;

  canvas.addEventListener('pointerdown', (e) => {
    canvas.setPointerCapture(e.pointerId);
    pointers.set(e.pointerId, [e.clientX, e.clientY]);
    if (pointers.size === 2) {
      const [p, q] = [...pointers.values()];
      pinchDistance = Math.hypot(p[0] - q[0], p[1] - q[1]);
    }
  });
  canvas.addEventListener('pointermove', (e) => {
    const previous = pointers.get(e.pointerId);
    if (!previous) return;
    const current = [e.clientX, e.clientY];
    pointers.set(e.pointerId, current);
    if (pointers.size === 1) {
      const dx = current[0] - previous[0], dy = current[1] - previous[1];
      const length = Math.hypot(dx, dy);
      if (length === 0) return;
      const angle = 4 * length / Math.max(canvas.clientWidth, canvas.clientHeight);
      orientation = multiply(rotation([dy / length, dx / length, 0], angle), orientation);
    } else if (pointers.size === 2) {
      const [p, q] = [...pointers.values()];
      const d = Math.hypot(p[0] - q[0], p[1] - q[1]);
      if (pinchDistance > 0 && d > 0) zoom = Math.min(20, Math.max(0.05, zoom * pinchDistance / d));
      pinchDistance = d;
    }
    redraw();
  });
  const release = (e) => { pointers.delete(e.pointerId); pinchDistance = 0; };
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    zoom = Math.min(20, Math.max(0.05, zoom * Math.exp(e.deltaY * 0.001)));
    redraw();
  }, { passive: false });
  canvas.addEventListener('dblclick', fitView);
  window.addEventListener('keydown', (e) => {
    if ((e.key !== 'u' && e.key !== 'U') || e.ctrlKey || e.metaKey || e.altKey) return;
    const current = upAxis !== null ? upAxis : JSON.parse(canvas.dataset.view || '{"up":"y"}').up;
    upAxis = upAxes[(upAxes.indexOf(current) + 1) % upAxes.length];
    fitView();
  });
  window.addEventListener('resize', redraw);

  // ---- start -------------------------------------------------------------

  let glError = '';
  try {
    glError = initGL();
  } catch (e) {
    glError = String(e.message || e);
  }
  if (glError) {
    // The shape still decodes (and the title still reports it); only the picture is missing.
    errorEl.textContent = 'no picture: ' + glError;
    program = null;
  }
  load().catch((e) => fail(String(e && e.message ? e.message : e)));
})();
