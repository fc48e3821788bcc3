import { defineConfig } from "vite";

// `npm run build` writes dist/, which is committed: `strata serve` serves it at `/` with no npm
// step on the machine that runs the server.
export default defineConfig({
  base: "./",
  build: {
    outDir: "dist",
    emptyOutDir: true,
    target: "es2022",
    chunkSizeWarningLimit: 1024,
    reportCompressedSize: false,
  },
  server: {
    proxy: {
      "/v1": { target: "http://127.0.0.1:8080", ws: true },
    },
  },
});
