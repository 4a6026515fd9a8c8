import { defineConfig, type Plugin } from "vite";
import { wasmBase64 } from "./vite.wasm-base64";

/** `import b64 from "./x.wasm?base64"`: the file's bytes as a base64 string, in the bundle. The
 * glue's default location of the module (used only when init() is given nothing) would be inlined
 * a second time: the widget always passes the bytes, so the glue gets none. */
function base64Wasm(): Plugin {
  return wasmBase64(
    "poinsot-wasm-base64",
    "vite.widget.config.ts",
    "(() => { throw new Error('poinsot widget: the core is passed as bytes'); })()",
  );
}

// The notebook widget (src/widget.ts): ONE ES module, the WebAssembly core inlined in it, and its
// stylesheet beside it, into the Python package (poinsot.widgets loads both; git-ignored, shipped
// in the wheel). Built after the lab (whose build empties python/poinsot/lab, not this folder).
export default defineConfig({
  plugins: [base64Wasm()],
  build: {
    outDir: "../python/poinsot/widgets/static",
    emptyOutDir: true,
    target: "es2022",
    chunkSizeWarningLimit: 4096,
    lib: { entry: "src/widget.ts", formats: ["es"], fileName: () => "widget.js", cssFileName: "widget" },
  },
});
