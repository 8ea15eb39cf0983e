// The side-by-side preview on the page, with the desktop preview's keys
// (docs/preview.md, docs/web.md): the physical head moved by the keyboard and
// turned by the mouse, walked by the module's walker, drawn each animation
// frame into the canvas, and the HUD line under it.
const speed = 1.4;  // m/s, Shift ×3

// WebXR's orientation of a head at (yaw, pitch), degrees: R_y(yaw) · R_x(pitch),
// as math::head_rotation with no roll.
export function yawPitchQuaternion(yawDeg, pitchDeg) {
  const y = (yawDeg * Math.PI) / 360, p = (pitchDeg * Math.PI) / 360;
  const cy = Math.cos(y), sy = Math.sin(y), cp = Math.cos(p), sp = Math.sin(p);
  return [cy * sp, sy * cp, -sy * sp, cy * cp];
}

export function startPreview({ api, canvas, showMessage }) {
  const hud = document.getElementById('hud');
  const state = {
    head: { x: 0, y: 1.6, z: 0, yaw: 0, pitch: 0 },
    keys: new Set(), running: true, hud: true, hand: false, handDistance: 0.4,
    ipd: 0.064, maxDepth: 8, clip: 'clip-distance', cull: true,
    lastTime: null, frames: 0, fpsTime: 0, fps: 0, lastStatus: null, teleports: 0,
  };

  function restart() {
    const info = JSON.parse(api.layoutInfo() || '{}');
    if (info.start) {
      state.head = { x: info.start[0], y: info.start[1], z: info.start[2], yaw: info.start[3], pitch: 0 };
    }
    state.teleports = 0;
    api.reset && api.reset();
  }

  function request() {
    const w = Math.max(16, Math.floor(canvas.clientWidth / 2)), h = Math.max(9, Math.round((w * 9) / 16));
    if (canvas.width !== 2 * w || canvas.height !== h) { canvas.width = 2 * w; canvas.height = h; }
    const h0 = state.head;
    const r = {
      space: 'layout',
      head: { position: [h0.x, h0.y, h0.z], orientation: yawPitchQuaternion(h0.yaw, h0.pitch) },
      size: [w, h], ipd: state.ipd, fov_y: 90, max_depth: state.maxDepth, clip: state.clip, cull: state.cull,
      time: performance.now() / 1000,
    };
    if (state.hand) {
      // The right hand held out in front, the left at the side (docs/preview.md, G).
      const yaw = (h0.yaw * Math.PI) / 180;
      const fwd = [-Math.sin(yaw), 0, -Math.cos(yaw)], right = [Math.cos(yaw), 0, -Math.sin(yaw)];
      const at = (f, r1, up) => [h0.x + f * fwd[0] + r1 * right[0], h0.y + up, h0.z + f * fwd[2] + r1 * right[2]];
      const q = yawPitchQuaternion(h0.yaw, 0);
      r.hands = [{ position: at(0.1, -0.2, -0.7), orientation: q },
                 { position: at(state.handDistance, 0.12, -0.12), orientation: q }];
    }
    return r;
  }

  function move(dt) {
    const k = state.keys, h = state.head;
    const f = (k.has('KeyW') || k.has('ArrowUp') ? 1 : 0) - (k.has('KeyS') || k.has('ArrowDown') ? 1 : 0);
    const s = (k.has('KeyD') || k.has('ArrowRight') ? 1 : 0) - (k.has('KeyA') || k.has('ArrowLeft') ? 1 : 0);
    const u = (k.has('KeyE') ? 1 : 0) - (k.has('KeyQ') ? 1 : 0);
    const v = speed * (k.has('ShiftLeft') || k.has('ShiftRight') ? 3 : 1) * dt;
    const yaw = (h.yaw * Math.PI) / 180;
    h.x += v * (-Math.sin(yaw) * f + Math.cos(yaw) * s);
    h.z += v * (-Math.cos(yaw) * f - Math.sin(yaw) * s);
    h.y = Math.min(3, Math.max(0.2, h.y + v * u));
  }

  function showHud(status) {
    if (!state.hud) { hud.textContent = ''; return; }
    const h = state.head;
    hud.textContent = `room ${status.room}   teleports ${state.teleports}   ` +
      `head ${h.x.toFixed(2)} ${h.y.toFixed(2)} ${h.z.toFixed(2)}  yaw ${h.yaw.toFixed(0)}°   ` +
      `depth ${state.maxDepth}   ipd ${(state.ipd * 1000).toFixed(0)} mm   ` +
      `${status.ms.toFixed(1)} ms (CPU) a frame, ${state.fps.toFixed(0)} fps`;
  }

  // One frame of the preview (the headset session draws its own instead).
  function frame() {
    const r = request();
    if (api.frame(JSON.stringify(r)) !== 0) {
      showMessage(api.message());
      return null;
    }
    const status = JSON.parse(api.status());
    state.teleports += status.teleports.length;
    state.lastStatus = status;
    showHud(status);
    return status;
  }

  function tick(time) {
    if (state.running) {
      const dt = state.lastTime === null ? 0 : Math.min(0.1, (time - state.lastTime) / 1000);
      state.lastTime = time;
      move(dt);
      frame();
      state.frames += 1;
      if (time - state.fpsTime > 1000) { state.fps = (1000 * state.frames) / (time - state.fpsTime); state.frames = 0; state.fpsTime = time; }
    }
    requestAnimationFrame(tick);
  }

  canvas.addEventListener('click', () => canvas.requestPointerLock && canvas.requestPointerLock());
  canvas.addEventListener('mousemove', (e) => {
    if (document.pointerLockElement !== canvas && !(e.buttons & 1)) return;
    state.head.yaw -= e.movementX * 0.15;
    state.head.pitch = Math.max(-89, Math.min(89, state.head.pitch - e.movementY * 0.15));
  });
  window.addEventListener('keydown', (e) => {
    if (e.target instanceof HTMLInputElement) return;
    state.keys.add(e.code);
    switch (e.code) {
      case 'KeyR': restart(); break;
      case 'KeyH': state.hud = !state.hud; break;
      case 'KeyG': state.hand = !state.hand; break;
      case 'Comma': state.handDistance = Math.max(0.1, state.handDistance - 0.05); break;
      case 'Period': state.handDistance = Math.min(1, state.handDistance + 0.05); break;
      case 'BracketLeft': state.maxDepth = Math.max(0, state.maxDepth - 1); break;
      case 'BracketRight': state.maxDepth = Math.min(250, state.maxDepth + 1); break;
      case 'Minus': state.ipd = Math.max(0, state.ipd - 0.002); break;
      case 'Equal': state.ipd = Math.min(0.2, state.ipd + 0.002); break;
      case 'KeyC': state.clip = state.clip === 'clip-distance' ? 'oblique' : 'clip-distance'; break;
      case 'KeyX': state.cull = !state.cull; break;
      case 'KeyP': {
        const a = document.createElement('a');
        a.href = canvas.toDataURL('image/png');
        a.download = 'screenshot.png';
        a.click();
        break;
      }
      default: return;
    }
    e.preventDefault();
  });
  window.addEventListener('keyup', (e) => state.keys.delete(e.code));
  requestAnimationFrame(tick);
  return { state, restart, frame, request, pause: () => { state.running = false; }, resume: () => { state.running = true; } };
}
