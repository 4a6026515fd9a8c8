import { defineConfig, type Plugin } from "vite";
import { wasmBase64 } from "./vite.wasm-base64";

// The lab as ONE self-contained HTML file (`poinsot lab --export FILE.html`, issue 23 item 2): the
// page of vite.config.ts with its script, stylesheet and WebAssembly core inside the HTML, so that
// it opens by double-click from disk (file://, where a browser fetches no relative file and runs
// no module worker), offline, and can be e-mailed or put on any web space. web/build.sh builds it
// after the page, into target/lab-export (git-ignored), and copies the one file to
// python/poinsot/lab/poinsot-lab.html (git-ignored, in the wheel with the page).

/** The glue's default location of the core (a fetch of a relative file, refused under file://)
 * becomes the core's bytes, decoded from base64 inlined in the bundle: `init()` fetches nothing. */
function wasmInline(): Plugin {
  const bytes =
    "(() => { const s = atob(__poinsotCore); const b = new Uint8Array(s.length); " +
    "for (let i = 0; i < s.length; i++) b[i] = s.charCodeAt(i); return b; })()";
  return wasmBase64(
    "poinsot-export-wasm",
    "vite.export.config.ts",
    bytes,
    'import __poinsotCore from "./poinsot_wasm_bg.wasm?base64";\n',
  );
}

/** What the file may load: its own inline script, styles and WebAssembly, data: and blob: images
 * (three.js textures, the favicon); no request to anywhere (a meta CSP, honoured under file://). */
export const EXPORT_CSP =
  "default-src 'none'; script-src 'unsafe-inline' 'wasm-unsafe-eval'; style-src 'unsafe-inline'; " +
  "img-src data: blob:; connect-src data: blob:; base-uri 'none'; form-action 'none'";

/** Replaces the built page's <script src> and <link rel=stylesheet> by the chunk and stylesheet
 * themselves, drops them from the bundle, and adds the CSP: the bundle is index.html alone. */
function singleFile(): Plugin {
  return {
    name: "poinsot-export-single-file",
    enforce: "post",
    generateBundle(_options, bundle) {
      const html = bundle["index.html"];
      if (!html || html.type !== "asset") this.error("no index.html in the bundle");
      let text = String(html.source);
      const inlined = new Set<string>();
      const body = (ref: string) => {
        const name = ref.replace(/^\.\//, "");
        const item = bundle[name];
        if (!item) this.error(`index.html refers to ${ref}, which is not in the bundle`);
        inlined.add(name);
        return item.type === "chunk" ? item.code : String(item.source);
      };
      text = text.replace(/<script type="module" crossorigin src="([^"]+)"><\/script>/g, (_m, ref: string) => {
        const code = body(ref);
        // "</script" would end the element early, "<!--" would change how it is parsed.
        if (code.includes("<!--")) this.error(`${ref} contains "<!--": it cannot be inlined as it is`);
        return `<script type="module">${code.replace(/<\/script/gi, "<\\/script")}</script>`;
      });
      text = text.replace(/<link rel="stylesheet" crossorigin href="([^"]+)">/g, (_m, ref: string) => {
        const css = body(ref);
        return `<style>${css.replace(/<\/style/gi, "<\\/style")}</style>`;
      });
      text = text.replace(
        /<meta charset="utf-8" \/>/,
        (m) => `${m}\n    <meta http-equiv="Content-Security-Policy" content="${EXPORT_CSP}" />`,
      );
      if (!text.includes("Content-Security-Policy")) this.error("index.html has no <meta charset>: the CSP was not added");
      for (const name of Object.keys(bundle)) {
        if (name === "index.html") continue;
        if (!inlined.has(name)) this.error(`${name} is in the bundle but not inlined: the file would not be self-contained`);
        delete bundle[name];
      }
      html.source = text;
    },
  };
}

export default defineConfig({
  base: "./",
  plugins: [wasmInline(), singleFile()],
  build: {
    outDir: "../target/lab-export",
    emptyOutDir: true,
    target: "es2022",
    modulePreload: false,
    cssCodeSplit: false,
    assetsInlineLimit: () => true,
    chunkSizeWarningLimit: 4096,
    rolldownOptions: { output: { codeSplitting: false } },
  },
});
