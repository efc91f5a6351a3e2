// Pictures out of the page: saving a data URL or a Blob as a file the browser downloads.

export function download(source: string | Blob, name: string): void {
  const url = typeof source === "string" ? source : URL.createObjectURL(source);
  const link = document.createElement("a");
  link.href = url;
  link.download = name;
  document.body.append(link);
  link.click();
  link.remove();
  if (typeof source !== "string") window.setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** A file name with the simulation time in it, e.g. eyesim-3d-t12.34.png. */
export function timedName(what: string, time: number, extension: string): string {
  return `eyesim-${what}-t${time.toFixed(2)}.${extension}`;
}
