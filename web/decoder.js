// gab's decoding session for the viewer: takes a .gab file's bytes as they
// arrive and, each time another chunk is complete, decodes the prefix of
// whole chunks in WebAssembly (gab_web.js, web/gab_web.cpp) and hands out the
// shape ready to draw: positions, normals and triangles, and for the first
// one its bounds and principal axes. No DOM and no WebGL, so the same code
// runs in a Web Worker (worker.js) or, where there is none, on the page's
// own thread (viewer.js loads it there). Hand-written, no libraries.
//
// createGabDecoder(gab, post) takes the module (createGabModule's) and a
// function post(message, transfer) for what it says; it returns
// { receive(message) } for what it is told. Messages in:
//   {type: 'options', stopLevel, flat, total}
//                                       before the bytes: stop at level
//                                       stopLevel (-1: none), flat shading,
//                                       the file's size (0: unknown)
//   {type: 'bytes', bytes, arrivedMs}   the file's next bytes (an ArrayBuffer)
//                                       and when the page had them (its clock)
//   {type: 'end'}                       the stream has ended
// Messages out (each typed array's buffer in `transfer`):
//   {type: 'decoding', level, bytes}    a level's decode starts
//   {type: 'shape', level, info, bytes, decodeMs, arrivedMs,
//    positions, normals, indices, bounds, axes}
//                                       a level is decoded (bounds and axes
//                                       with the first only)
//   {type: 'done', n, anchors}          the last level has been posted
//   {type: 'error', message}            nothing more follows
'use strict';

function createGabDecoder(gab, post) {
  let stopLevel = -1;
  let flat = false;
  let total = 0;           // Content-Length (0: unknown)
  let received = 0;        // bytes in the module's buffer
  let streamDone = false;
  let decodedChunks = 0;   // complete chunks of the last level posted
  let shown = null;        // what the decoder said of it
  let stepPending = false;
  let finished = false;    // done or failed: nothing more happens
  const arrivals = [];     // [end offset, the page's arrival time] per message of bytes

  function fail(message) {
    if (finished) return;
    finished = true;
    post({ type: 'error', message: message });
  }

  // Copies `bytes` after the ones received so far, growing the module's
  // buffer geometrically (the one copy a stream into WebAssembly needs).
  function append(bytes) {
    const need = received + bytes.length;
    const ptr = gab._gab_web_buffer(Math.max(need, total, 2 * received));
    if (!ptr) throw new Error('out of memory for ' + need + ' bytes');
    gab.HEAPU8.set(bytes, ptr + received);  // HEAPU8 afresh: the memory may have grown
    received = need;
  }

  // When the page had the first `size` bytes.
  function arrivedAt(size) {
    for (const [end, ms] of arrivals) {
      if (end >= size) return ms;
    }
    return arrivals.length ? arrivals[arrivals.length - 1][1] : 0;
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
      if (!decodeAndPost(size, frames - 1)) return;
    }
    if (shown && (last || isComplete(shown))) conclude(shown);
  }

  function isComplete(info) {
    return info.chunks === info.chunksInFile && info.anchors === info.anchorsInFile;
  }

  // The last level has been posted: done, or the file ended early.
  function conclude(info) {
    if (isComplete(info) || stopLevel >= 0) {
      finished = true;
      post({ type: 'done', n: info.n, anchors: info.anchors });
    } else {
      fail('the file ends inside chunk ' + info.chunks + ' of ' + info.chunksInFile +
           ' (showing the first ' + info.chunks + ')');
    }
  }

  // Decodes the first `size` bytes and posts the shape; false on an error.
  function decodeAndPost(size, level) {
    post({ type: 'decoding', level: level, bytes: size });
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
    };
    // Copies out of the module's memory (it is reused by the next decode),
    // then handed over without another.
    let positions = new Float32Array(gab.HEAPF32.buffer, gab._gab_web_positions(), 3 * info.n).slice();
    let indices = new Uint32Array(gab.HEAPU32.buffer, gab._gab_web_indices(), 3 * info.t).slice();
    let bounds = null, axes = null;
    if (shown === null) {
      bounds = boundingBox(positions);
      axes = principalAxes(positions, indices, bounds.center);
    }
    if (flat) [positions, indices] = unshared(positions, indices);
    const normals = vertexNormals(positions, indices);
    decodedChunks = info.chunks;
    shown = info;
    post({
      type: 'shape', level: info.chunks - 1, info: info, bytes: size, decodeMs: decodeMs,
      arrivedMs: arrivedAt(size), positions: positions, normals: normals, indices: indices,
      bounds: bounds, axes: axes,
    }, [positions.buffer, normals.buffer, indices.buffer]);
    return true;
  }

  function receive(message) {
    if (finished) return;
    if (message.type === 'options') {
      stopLevel = message.stopLevel;
      flat = message.flat;
      total = message.total;
    } else if (message.type === 'bytes') {
      try {
        append(new Uint8Array(message.bytes));
      } catch (e) {
        return fail('the decoder stopped: ' + e.message);
      }
      arrivals.push([received, message.arrivedMs]);
      schedule();
    } else if (message.type === 'end') {
      streamDone = true;
      schedule();
    }
  }

  return { receive: receive };
}

// ---- the shape's geometry ------------------------------------------------

function boundingBox(positions) {
  let lx = Infinity, ly = Infinity, lz = Infinity, hx = -Infinity, hy = -Infinity, hz = -Infinity;
  for (let i = 0; i < positions.length; i += 3) {
    const x = positions[i], y = positions[i + 1], z = positions[i + 2];
    if (x < lx) lx = x;
    if (x > hx) hx = x;
    if (y < ly) ly = y;
    if (y > hy) hy = y;
    if (z < lz) lz = z;
    if (z > hz) hz = z;
  }
  if (positions.length === 0) { lx = ly = lz = 0; hx = hy = hz = 1; }
  return {
    center: [0.5 * (lx + hx), 0.5 * (ly + hy), 0.5 * (lz + hz)],
    radius: 0.5 * Math.hypot(hx - lx, hy - ly, hz - lz) || 1,
  };
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
    normals[a] += nx;
    normals[a + 1] += ny;
    normals[a + 2] += nz;
    normals[b] += nx;
    normals[b + 1] += ny;
    normals[b + 2] += nz;
    normals[c] += nx;
    normals[c + 1] += ny;
    normals[c + 2] += nz;
  }
  for (let k = 0; k < normals.length; k += 3) {
    const x = normals[k], y = normals[k + 1], z = normals[k + 2];
    const len = Math.sqrt(x * x + y * y + z * z) || 1;
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

// The surface's principal axes, the largest spread first: eigenvectors of
// its covariance about `center`, each triangle's second moment taken
// exactly (area / 12 * (aa' + bb' + cc' + ss'), s = a + b + c), so uneven
// sampling does not pull them. Cyclic Jacobi rotations on the 3 x 3 matrix.
// The viewer's first view looks along the last (viewer.js, homeView).
function principalAxes(positions, indices, center) {
  let area = 0;
  let mx = 0, my = 0, mz = 0;                                  // area times the centroid
  let sxx = 0, syy = 0, szz = 0, sxy = 0, sxz = 0, syz = 0;  // 12 times the second moments
  const p = positions;
  for (let k = 0; k + 2 < indices.length; k += 3) {
    const ia = 3 * indices[k], ib = 3 * indices[k + 1], ic = 3 * indices[k + 2];
    const ax = p[ia] - center[0], ay = p[ia + 1] - center[1], az = p[ia + 2] - center[2];
    const bx = p[ib] - center[0], by = p[ib + 1] - center[1], bz = p[ib + 2] - center[2];
    const cx = p[ic] - center[0], cy = p[ic + 1] - center[1], cz = p[ic + 2] - center[2];
    const sx = ax + bx + cx, sy = ay + by + cy, sz = az + bz + cz;
    const ux = bx - ax, uy = by - ay, uz = bz - az;
    const vx = cx - ax, vy = cy - ay, vz = cz - az;
    const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const w = 0.5 * Math.sqrt(nx * nx + ny * ny + nz * nz);
    area += w;
    mx += w * sx / 3;
    my += w * sy / 3;
    mz += w * sz / 3;
    sxx += w * (ax * ax + bx * bx + cx * cx + sx * sx);
    syy += w * (ay * ay + by * by + cy * cy + sy * sy);
    szz += w * (az * az + bz * bz + cz * cz + sz * sz);
    sxy += w * (ax * ay + bx * by + cx * cy + sx * sy);
    sxz += w * (ax * az + bx * bz + cx * cz + sx * sz);
    syz += w * (ay * az + by * bz + cy * cz + sy * sz);
  }
  const second = [sxx / 12, syy / 12, szz / 12, sxy / 12, sxz / 12, syz / 12];  // xx yy zz xy xz yz
  const mean = [mx, my, mz];
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
