import { readFileSync } from "node:fs";
import { defineConfig, type Plugin } from "vite";

/** `import b64 from "./x.wasm?base64"`: the file's bytes as a base64 string, in the bundle. */
function base64Wasm(): Plugin {
  return {
    name: "poinsot-wasm-base64",
    enforce: "pre",
    load(id) {
      if (!id.endsWith(".wasm?base64")) return null;
      const file = id.slice(0, -"?base64".length);
      this.addWatchFile(file);
      return `export default ${JSON.stringify(readFileSync(file).toString("base64"))};`;
    },
    // The glue's default location of the module (used only when init() is given nothing) would be
    // inlined a second time: the widget always passes the bytes, so the glue gets none.
    transform(code, id) {
      if (!id.endsWith("/wasm/poinsot_wasm.js")) return null;
      const at = "new URL('poinsot_wasm_bg.wasm', import.meta.url)";
      if (!code.includes(at)) this.error(`${id}: the glue no longer loads ${at}; update vite.widget.config.ts`);
      return { code: code.replace(at, "(() => { throw new Error('poinsot widget: the core is passed as bytes'); })()"), map: null };
    },
  };
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
