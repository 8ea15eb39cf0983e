// The side-by-side preview on the page (filled in by the page's module).
export function startPreview(module) {
  return { module };
}
