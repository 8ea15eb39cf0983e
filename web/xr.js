// The headset session (docs/web.md, "In a headset"): Enter VR starts an
// immersive-vr session; each frame the viewer pose goes to the module's
// walker as the physical head (WebXR's local-floor space, the layout's
// start at its origin; local where there is no floor), each view's pose
// relative to the head and its projection become that eye's pose and
// angles, and the frame is drawn into the layer's framebuffer, each eye into
// its viewport. Controllers' grip poses are the layout's hands.

// Quaternions as [x, y, z, w].
export function quatMultiply(a, b) {
  return [a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
          a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
          a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
          a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]];
}
const conjugate = (q) => [-q[0], -q[1], -q[2], q[3]];
function rotate(q, v) {
  const p = quatMultiply(quatMultiply(q, [v[0], v[1], v[2], 0]), conjugate(q));
  return [p[0], p[1], p[2]];
}
const vec = (p) => [p.x, p.y, p.z];
const quat = (o) => [o.x, o.y, o.z, o.w];

// A head pose in the layout's coordinates (x, y, z, yaw, pitch, roll; as
// --pose and path files give it) in local-floor space, where the layout's
// start stands on the floor at the origin facing -z (src/web/web_view.cpp):
// {position, orientation}. For putting an emulated headset somewhere.
export function layoutToFloor(start, p) {
  const [sx, , sz, syaw] = start;
  const rad = (d) => (d * Math.PI) / 180;
  const q = (axis, deg) => { const h = rad(deg) / 2; const v = [0, 0, 0, Math.cos(h)]; v[axis] = Math.sin(h); return v; };
  const c = Math.cos(rad(syaw)), s = Math.sin(rad(syaw));
  const dx = p[0] - sx, dz = p[2] - sz;
  // R_y(-yaw_start) · (p - the start on the floor); R_y(yaw) · R_x(pitch) · R_z(-roll)
  return { position: [c * dx - s * dz, p[1], s * dx + c * dz],
           orientation: quatMultiply(q(1, -syaw), quatMultiply(q(1, p[3]), quatMultiply(q(0, p[4]), q(2, -p[5])))) };
}

// OpenXR's angles (degrees: left, right, up, down) of a WebGL projection
// matrix (column-major): the image plane at z = -1 spans the tangents.
export function fovAngles(m) {
  const deg = (t) => (Math.atan(t) * 180) / Math.PI;
  return [deg((m[8] - 1) / m[0]), deg((m[8] + 1) / m[0]), deg((m[9] + 1) / m[5]), deg((m[9] - 1) / m[5])];
}

// The page's frame request (src/web/web_view.hpp) for a viewer pose.
export function xrFrameRequest(pose, layer, space, framebuffer, hands) {
  const headPosition = vec(pose.transform.position), headOrientation = quat(pose.transform.orientation);
  const toHead = conjugate(headOrientation);
  const eyes = [], viewports = [];
  for (const view of pose.views.slice(0, 2)) {
    const p = vec(view.transform.position);
    eyes.push({
      position: rotate(toHead, [p[0] - headPosition[0], p[1] - headPosition[1], p[2] - headPosition[2]]),
      orientation: quatMultiply(toHead, quat(view.transform.orientation)),
      fov: fovAngles(view.projectionMatrix),
    });
    const v = layer.getViewport(view);
    viewports.push([v.x, v.y, v.width, v.height]);
  }
  const request = {
    space, head: { position: headPosition, orientation: headOrientation }, eyes,
    size: [viewports[0][2], viewports[0][3]], target: { framebuffer, viewports },
  };
  if (hands) request.hands = hands;
  return request;
}

export async function setUpXr({ module, api, canvas, preview, showMessage }) {
  const button = document.getElementById('enter-vr');
  const xr = { session: null, hold: false, layoutToFloor, frames: 0, lastStatus: null, lastRequest: null, teleports: [], onFrame: null };
  const supported = !!navigator.xr && (await navigator.xr.isSessionSupported('immersive-vr').catch(() => false));
  button.disabled = !supported;
  if (!supported) button.title = 'This browser offers no immersive-vr WebXR session';

  // The layer's framebuffer as a name the module's GL calls know (0: the
  // canvas's, which is what a layer without one of its own draws into).
  function framebufferName(framebuffer) {
    if (!framebuffer) return 0;
    if (!framebuffer.name) {
      const id = module.GL.getNewId(module.GL.framebuffers);
      framebuffer.name = id;
      module.GL.framebuffers[id] = framebuffer;
    }
    return framebuffer.name;
  }

  function handsOf(frame, space) {
    const poses = {};
    for (const source of xr.session.inputSources) {
      if (!source.gripSpace || (source.handedness !== 'left' && source.handedness !== 'right')) continue;
      const p = frame.getPose(source.gripSpace, space);
      if (p) poses[source.handedness] = { position: vec(p.transform.position), orientation: quat(p.transform.orientation) };
    }
    return poses.left && poses.right ? [poses.left, poses.right] : null;
  }

  function onFrame(time, frame) {
    const session = frame.session;
    session.requestAnimationFrame(onFrame);
    if (xr.hold) return;  // a test putting the headset somewhere first
    const pose = frame.getViewerPose(xr.space);
    if (!pose) return;
    const layer = session.renderState.baseLayer;
    const request = xrFrameRequest(pose, layer, xr.spaceName, framebufferName(layer.framebuffer),
                                   handsOf(frame, xr.space));
    request.time = time / 1000;
    xr.lastRequest = request;
    if (api.frame(JSON.stringify(request)) !== 0) {
      showMessage(api.message());
      return;
    }
    xr.lastStatus = JSON.parse(api.status());
    xr.teleports.push(...xr.lastStatus.teleports);
    xr.frames += 1;
    if (xr.onFrame) xr.onFrame(xr.lastStatus, request);
  }

  xr.enter = async function enter() {
    const session = await navigator.xr.requestSession('immersive-vr', { optionalFeatures: ['local-floor'] });
    const gl = module.GL.currentContext.GLctx;
    if (gl.makeXRCompatible) await gl.makeXRCompatible();
    const layer = new XRWebGLLayer(session, gl, { antialias: false, depth: true, stencil: true, alpha: false });
    session.updateRenderState({ baseLayer: layer });
    try {
      xr.space = await session.requestReferenceSpace('local-floor');
      xr.spaceName = 'floor';
    } catch (e) {
      xr.space = await session.requestReferenceSpace('local');
      xr.spaceName = 'local';  // its origin at the eyes: the start's head there
    }
    xr.session = session;
    xr.frames = 0;
    xr.teleports = [];
    api.reset();
    preview.pause();
    session.addEventListener('end', () => { xr.session = null; preview.resume(); });
    session.requestAnimationFrame(onFrame);
  };
  xr.exit = async () => { if (xr.session) await xr.session.end(); };
  button.addEventListener('click', () => xr.enter().catch((e) => showMessage('Enter VR: ' + e.message)));
  return xr;
}
