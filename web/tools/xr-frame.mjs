// Placeholder until the headset path lands.
export async function xrRender() { throw new Error('--xr is not built yet'); }
