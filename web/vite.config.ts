import { defineConfig } from "vite";

// The built page lives inside the Python package (served by `poinsot lab`); relative asset
// paths so that it works from any mount point.
export default defineConfig({
  base: "./",
  // The dev server may serve the one file the scenes import from outside web/: the parameters
  // they share with the notebook widgets (python/poinsot/widgets/scenes.json).
  server: { fs: { allow: [".", "../python/poinsot/widgets/scenes.json"] } },
  build: {
    outDir: "../python/poinsot/lab",
    emptyOutDir: true,
    target: "es2022",
    chunkSizeWarningLimit: 1024,
  },
});
