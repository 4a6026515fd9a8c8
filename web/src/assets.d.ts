// The widget's bundled core (vite.widget.config.ts's plugin): a .wasm file's bytes in base64.
declare module "*.wasm?base64" {
  const base64: string;
  export default base64;
}
