// The viewer's Web Worker: loads the decoder (decoder.js, and the
// WebAssembly module gab_web.js / gab_web.wasm) and runs its decoding
// session on this thread, so the page keeps answering input while a level
// decodes. viewer.js starts it, waits for {type: 'ready'} (or an
// {type: 'error', message} saying why the decoder did not load), then speaks
// decoder.js's messages with it; shapes come back with their buffers
// transferred, not copied.
'use strict';

let session = null;
const early = [];  // messages that came before the module

function post(message, transfer) {
  postMessage(message, transfer || []);
}

onmessage = (e) => {
  if (session) session.receive(e.data);
  else early.push(e.data);
};

(async function start() {
  try {
    importScripts('decoder.js');
  } catch (e) {
    return post({ type: 'error', message: 'decoder.js did not load' });
  }
  try {
    importScripts('gab_web.js');
  } catch (e) {
    return post({ type: 'error', message: 'gab_web.js did not load' });
  }
  if (typeof createGabModule !== 'function') return post({ type: 'error', message: 'gab_web.js did not load' });
  let gab;
  try {
    gab = await createGabModule();
  } catch (e) {
    return post({ type: 'error', message: 'the decoder did not load: ' + e });
  }
  session = createGabDecoder(gab, post);
  post({ type: 'ready' });
  for (const message of early.splice(0)) session.receive(message);
})();
