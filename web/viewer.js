// gab's progressive viewer: streams a .gab file, has it decoded in
// WebAssembly each time another chunk has completely arrived, and draws the
// shape with WebGL. The decoding (decoder.js over gab_web.js, web/gab_web.cpp)
// runs in a Web Worker (worker.js): this thread only fetches, draws and
// answers input. Hand-written, no libraries.
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
//   worker=0        decode on the page's thread, as where there is no Web
//                   Worker (for comparisons: the page pauses while a level decodes)
//
// For scripts: once the last level is shown, document.title is
// "gab: done n=<vertices> anchors=<anchors>"; on a bad file (decoder or HTTP
// error) it is "gab: error: <message>". Every level shown is a list item
// with data-level, data-anchors, data-bytes, data-total, data-decode-ms,
// data-arrived-ms (when the page had the level's last byte) and
// data-shown-ms (when it was drawn), both in ms since the page started; the
// canvas's data-view is the first view, {"toCamera": [x, y, z], "up": AXIS};
// the body's data-decoder says where the levels were decoded: "worker" or
// "page".
'use strict';

(function () {
  const params = new URLSearchParams(window.location.search);
  const fileName = params.get('file');
  const stopLevel = params.has('level') ? parseInt(params.get('level'), 10) : -1;
  const compact = params.get('compact') === '1';
  const flatShading = params.get('flat') === '1';
  const homeZoom = params.has('zoom') ? Math.min(20, Math.max(0.05, parseFloat(params.get('zoom')) || 1)) : 1;
  const useWorker = params.get('worker') !== '0';
  if (compact) document.body.classList.add('compact');

  const canvas = document.getElementById('view');
  const statusEl = document.getElementById('status');
  const progressEl = document.getElementById('progress');
  const pathEl = document.getElementById('path');
  const errorEl = document.getElementById('error');
  const levelsEl = document.getElementById('levels');
  const startTime = performance.now();

  // ---- page state --------------------------------------------------------

  let received = 0;        // bytes fetched so far
  let total = 0;           // Content-Length (0: unknown)
  let streamDone = false;
  let decoding = null;     // {level, since} while a level decodes
  let finished = false;    // done or failed: nothing more happens

  function kb(bytes) { return (bytes / 1024).toFixed(1) + ' KB'; }

  function fail(message) {
    if (finished) return;
    finish();
    document.title = 'gab: error: ' + message;
    errorEl.textContent = 'error: ' + message;
  }

  function finish() {
    finished = true;
    decoding = null;
    clearInterval(progressTimer);
    showProgress();
    stopDecoder();
  }

  // ---- the decoder: in a Web Worker, or on this thread ------------------
  //
  // The worker loads the WebAssembly module itself, while this thread sets
  // up WebGL and fetches. Messages for the decoder (decoder.js's) wait here until it is
  // ready, so a worker that cannot start leaves them to the fallback: the
  // same session on this thread, as where there is no Web Worker at all
  // (file://, an old browser); each level's decode then blocks the page.
  // Bytes go over with their buffers transferred, not copied.

  let sendToDecoder = null;  // (message, transfer) => void, once it is ready
  let waiting = [];          // [message, transfer] until then
  let stopDecoder = () => {};

  function send(message, transfer) {
    if (sendToDecoder) sendToDecoder(message, transfer || []);
    else waiting.push([message, transfer || []]);
  }

  function decoderReady(sender, where, why) {
    sendToDecoder = sender;
    document.body.dataset.decoder = where;
    if (where === 'page') pathEl.textContent = 'decoding on the page\'s thread (' + why + '): it pauses while a level decodes';
    for (const [message, transfer] of waiting.splice(0)) sender(message, transfer);
  }

  function startDecoder() {
    if (!useWorker) return startHere('worker=0');
    if (typeof Worker !== 'function') return startHere('no Web Worker in this browser');
    let worker;
    try {
      worker = new Worker('worker.js');
    } catch (e) {
      return startHere('no Web Worker here: ' + (e.message || e));
    }
    stopDecoder = () => worker.terminate();
    worker.onmessage = (e) => {
      if (e.data.type === 'ready') decoderReady((message, transfer) => worker.postMessage(message, transfer), 'worker');
      else fromDecoder(e.data);
    };
    worker.onerror = (e) => {
      e.preventDefault();
      if (sendToDecoder) return fail('the decoder stopped: ' + e.message);
      worker.terminate();
      startHere('the Web Worker did not start');
    };
  }

  function loadScript(src) {
    return new Promise((resolve, reject) => {
      const script = document.createElement('script');
      script.src = src;
      script.onload = resolve;
      script.onerror = () => reject(new Error(src + ' did not load'));
      document.head.appendChild(script);
    });
  }

  async function startHere(why) {
    stopDecoder = () => {};
    try {
      await loadScript('decoder.js');
      await loadScript('gab_web.js');
    } catch (e) {
      return fail(e.message);
    }
    if (typeof createGabModule !== 'function') return fail('gab_web.js did not load');
    let gab;
    try {
      gab = await createGabModule();
    } catch (e) {
      return fail('the decoder did not load: ' + e);
    }
    if (finished) return;
    const session = createGabDecoder(gab, fromDecoder);
    decoderReady((message) => session.receive(message), 'page', why);
  }

  function fromDecoder(message) {
    if (finished) return;
    if (message.type === 'decoding') {
      decoding = { level: message.level, since: performance.now() };
      showProgress();
    } else if (message.type === 'shape') {
      decoding = null;
      uploadMesh(message);
      draw();
      report(message);
      showProgress();
    } else if (message.type === 'done') {
      finish();
      document.title = 'gab: done n=' + message.n + ' anchors=' + message.anchors;
    } else if (message.type === 'error') {
      fail(message.message);
    }
  }

  // ---- the panel ----------------------------------------------------------

  // While a level decodes, which one and for how long; while bytes arrive,
  // how many. Refreshed by a timer, which also shows this thread is free.
  function showProgress() {
    let text = '';
    if (decoding) {
      const seconds = ((performance.now() - decoding.since) / 1000).toFixed(1);
      text = 'decoding' + (decoding.level >= 0 ? ' level ' + decoding.level : '') + '… ' + seconds + ' s';
    } else if (!finished && received > 0 && !streamDone) {
      text = 'received ' + kb(received) + (total ? ' of ' + kb(total) : '');
    }
    if (progressEl.textContent !== text) progressEl.textContent = text;
  }
  const progressTimer = setInterval(showProgress, 100);

  function report(shape) {
    const info = shape.info;
    const level = shape.level;
    let kind = '';
    if (info.detail) kind = ' (detail)';
    else if (info.refined) kind = ' (refinement)';
    const ms = shape.decodeMs.toFixed(0);
    const shownMs = performance.now() - startTime;
    statusEl.textContent =
      'level ' + level + kind + ' of ' + (info.chunksInFile - 1) +
      ' · anchors ' + info.anchors + ' / ' + info.anchorsInFile +
      ' · ' + kb(shape.bytes) + (total ? ' / ' + kb(total) : '') +
      (compact ? '' : ' · n = ' + info.n + ', ' + info.t + ' triangles · decoded in ' + ms + ' ms');
    const item = document.createElement('li');
    item.className = 'level';
    item.dataset.level = String(level);
    item.dataset.anchors = String(info.anchors);
    item.dataset.bytes = String(shape.bytes);
    item.dataset.total = String(total);
    item.dataset.decodeMs = ms;
    item.dataset.arrivedMs = (shape.arrivedMs - startTime).toFixed(0);
    item.dataset.shownMs = shownMs.toFixed(0);
    item.textContent = 'level ' + level + kind + ': ' + info.anchors + ' anchors' + ' at ' + kb(shape.bytes) +
      ', decoded in ' + ms + ' ms, shown at ' + shownMs.toFixed(0) + ' ms';
    levelsEl.appendChild(item);
  }

  // ---- streaming ---------------------------------------------------------

  async function load() {
    if (!fileName) return fail('no file given: open index.html?file=NAME.gab');
    document.getElementById('name').textContent = fileName;
    statusEl.textContent = 'fetching ' + fileName + '…';
    let response;
    try {
      response = await fetch(fileName);
    } catch (e) {
      return fail('cannot fetch ' + fileName + ': ' + e.message);
    }
    if (!response.ok) return fail('HTTP ' + response.status + ' ' + response.statusText + ' for ' + fileName);
    total = Number(response.headers.get('Content-Length')) || 0;
    send({ type: 'options', stopLevel: stopLevel, flat: flatShading, total: total });
    const reader = response.body.getReader();
    for (;;) {
      let chunk;
      try {
        chunk = await reader.read();
      } catch (e) {
        return fail('reading ' + fileName + ': ' + e.message);
      }
      if (finished) {
        reader.cancel();
        return;
      }
      if (chunk.done) break;
      const bytes = chunk.value;
      received += bytes.length;
      // The stream's chunks usually own their buffers: handed over whole.
      const buffer = bytes.byteOffset === 0 && bytes.byteLength === bytes.buffer.byteLength
        ? bytes.buffer : bytes.slice().buffer;
      send({ type: 'bytes', bytes: buffer, arrivedMs: performance.now() }, [buffer]);
    }
    streamDone = true;
    if (received === 0) return fail(fileName + ' is empty');
    send({ type: 'end' });
  }

  // ---- WebGL -------------------------------------------------------------

  let gl = null;
  let program = null, positionBuffer = null, normalBuffer = null, indexBuffer = null;
  let modelViewLocation = null, projectionLocation = null;
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
    gl = canvas.getContext('webgl2', { antialias: true, preserveDrawingBuffer: true }) ||
         canvas.getContext('webgl', { antialias: true, preserveDrawingBuffer: true });
    if (!gl) return 'WebGL is not available in this browser';
    const isWebGL2 = typeof WebGL2RenderingContext !== 'undefined' && gl instanceof WebGL2RenderingContext;
    if (!isWebGL2 && !gl.getExtension('OES_element_index_uint')) return 'WebGL lacks 32-bit indices';
    program = gl.createProgram();
    gl.attachShader(program, compile(gl.VERTEX_SHADER, vertexSource));
    gl.attachShader(program, compile(gl.FRAGMENT_SHADER, fragmentSource));
    gl.bindAttribLocation(program, 0, 'position');
    gl.bindAttribLocation(program, 1, 'normal');
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) return gl.getProgramInfoLog(program);
    // Asked once, here: a query waits for the GPU process to catch up, which
    // after a large upload would hold this thread for as long as the copy takes.
    modelViewLocation = gl.getUniformLocation(program, 'modelView');
    projectionLocation = gl.getUniformLocation(program, 'projection');
    positionBuffer = gl.createBuffer();
    normalBuffer = gl.createBuffer();
    indexBuffer = gl.createBuffer();
    gl.enable(gl.DEPTH_TEST);
    return '';
  }

  // The first level fixes the camera (the bounding box barely moves after):
  // each later level replaces the shape in place, so refinement is visible.
  // The decoder sends the normals and, with the first level, its bounds and
  // principal axes: nothing here is proportional to the shape but the upload.
  function uploadMesh(shape) {
    if (!program) return;
    if (!fitted) {
      center = shape.bounds.center;
      radius = shape.bounds.radius;
      axes = shape.axes;
      homeView();
      fitted = true;
    }
    gl.bindBuffer(gl.ARRAY_BUFFER, positionBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, shape.positions, gl.STATIC_DRAW);
    gl.bindBuffer(gl.ARRAY_BUFFER, normalBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, shape.normals, gl.STATIC_DRAW);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, indexBuffer);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, shape.indices, gl.STATIC_DRAW);
    indexCount = shape.indices.length;
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
  // -x, -y, -z) or the U key (the next axis) chooses another. The axes come
  // with the first level (decoder.js, principalAxes).

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
    gl.uniformMatrix4fv(modelViewLocation, false, modelView);
    gl.uniformMatrix4fv(projectionLocation, false, projection);
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

  // The worker starts loading the module first; WebGL is set up in a task
  // of its own, so the worker's start is not held behind it (a software
  // renderer can take a good part of a second to create its context).
  if (fileName) startDecoder();
  setTimeout(() => {
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
    } else {
      resize();  // the drawing buffer's size, before any shape: a new size waits for the GPU process
    }
    load().catch((e) => fail(String(e && e.message ? e.message : e)));
  }, 0);
})();
