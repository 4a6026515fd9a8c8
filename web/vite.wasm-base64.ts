import { readFileSync } from "node:fs";
import type { Plugin } from "vite";

/** The glue's default location of the core, a fetch of a file beside it. */
const GLUE_URL = "new URL('poinsot_wasm_bg.wasm', import.meta.url)";

/** The core's bytes in the bundle, for the one-file builds (vite.export.config.ts,
 * vite.widget.config.ts): `import b64 from "./x.wasm?base64"` gives the file's bytes as a base64
 * string, and the wasm-bindgen glue's {@link GLUE_URL} becomes `location` (an expression), with
 * `prelude` put before the glue's code (e.g. the import of the bytes that `location` decodes).
 * `config` names the config file in the error raised when the glue no longer has that URL. */
export function wasmBase64(name: string, config: string, location: string, prelude = ""): Plugin {
  return {
    name,
    enforce: "pre",
    load(id) {
      if (!id.endsWith(".wasm?base64")) return null;
      const file = id.slice(0, -"?base64".length);
      this.addWatchFile(file);
      return `export default ${JSON.stringify(readFileSync(file).toString("base64"))};`;
    },
    transform(code, id) {
      if (!id.endsWith("/wasm/poinsot_wasm.js")) return null;
      if (!code.includes(GLUE_URL)) this.error(`${id}: the glue no longer loads ${GLUE_URL}; update ${config}`);
      return { code: `${prelude}${code.replace(GLUE_URL, location)}`, map: null };
    },
  };
}
