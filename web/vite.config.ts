import { defineConfig } from "vite";

// The built page lives inside the Python package (served by `poinsot lab`); relative asset
// paths so that it works from any mount point.
export default defineConfig({
  base: "./",
  build: {
    outDir: "../python/poinsot/lab",
    emptyOutDir: true,
    target: "es2022",
    chunkSizeWarningLimit: 1024,
  },
});
