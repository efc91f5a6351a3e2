// Builds the viewer into the Python package's static assets, with stable names and no source maps.

import { defineConfig } from "vite";

export default defineConfig({
  // Relative asset URLs: the page works wherever the simulator serves it.
  base: "./",
  build: {
    outDir: "../src/eyesim/web/static",
    emptyOutDir: true,
    sourcemap: false,
    // three.js alone is over Vite's default 500 kB warning; one file is what we want.
    chunkSizeWarningLimit: 1024,
    rolldownOptions: {
      // the viewer and the robot editor (a page of its own)
      input: { index: "index.html", "robot-editor": "robot-editor.html" },
      output: {
        // Fixed names keep the committed bundle's diffs readable.
        entryFileNames: "assets/[name].js",
        chunkFileNames: "assets/[name].js",
        // What both pages use (three.js, the world builder, the common styles) goes into one
        // chunk with a name that says so.
        codeSplitting: { groups: [{ name: "shared", minShareCount: 2 }] },
        assetFileNames: "assets/[name][extname]",
      },
    },
  },
});
