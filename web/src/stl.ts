// Reading STL files for the inertia scene: binary and ASCII STL parsed to a triangle soup, then
// vertices with exactly equal coordinates merged (an STL stores every triangle with its own three
// corners; without merging every STL would look open). This is file parsing only: the mass
// properties, and every check that the mesh bounds a solid, are the core's (RigidBody.fromMesh).

/** An error named like the Python API's (the shell shows `name: message`). */
function meshError(message: string): Error {
  const e = new Error(message);
  e.name = "InvalidMeshError";
  return e;
}

/** The corners of every triangle of an STL file (9 numbers a triangle, file units). Binary when
 * the size is 84 + 50·n for the count n in the header, else ASCII (`solid … facet … vertex x y z`). */
export function parseStl(buf: ArrayBuffer): Float64Array {
  if (buf.byteLength >= 84) {
    const dv = new DataView(buf);
    const n = dv.getUint32(80, true);
    if (84 + 50 * n === buf.byteLength) {
      const out = new Float64Array(9 * n);
      for (let k = 0; k < n; k++) {
        const base = 84 + 50 * k + 12; // skip the normal: the winding is what counts
        for (let j = 0; j < 9; j++) out[9 * k + j] = dv.getFloat32(base + 4 * j, true);
      }
      return out;
    }
  }
  const text = new TextDecoder().decode(buf);
  if (!/^\s*solid\b/.test(text)) {
    throw meshError(`file: not an STL file (binary: size 84 + 50·n bytes; ASCII: starts with "solid"), got ${buf.byteLength} bytes`);
  }
  const values: number[] = [];
  const re = /\bvertex\s+(\S+)\s+(\S+)\s+(\S+)/g;
  for (let m = re.exec(text); m; m = re.exec(text)) {
    for (let j = 1; j <= 3; j++) {
      const x = Number(m[j]);
      if (!Number.isFinite(x)) throw meshError(`file: vertex ${values.length / 3} has a coordinate that is not a finite number: "${m[j]}"`);
      values.push(x);
    }
  }
  if (values.length % 9 !== 0) throw meshError(`file: ${values.length / 3} vertices do not make whole triangles`);
  return Float64Array.from(values);
}

/** A triangle soup with vertices of exactly equal coordinates merged (−0 counts as 0), as
 * `vertices` (3 numbers a vertex) and `faces` (3 indices a triangle, the file's winding). */
export function mergeVertices(soup: Float64Array): { vertices: Float64Array; faces: Float64Array } {
  const index = new Map<string, number>();
  const vertices: number[] = [];
  const faces = new Float64Array(soup.length / 3);
  for (let i = 0; i < soup.length / 3; i++) {
    const x = soup[3 * i] + 0, y = soup[3 * i + 1] + 0, z = soup[3 * i + 2] + 0;
    const key = `${x} ${y} ${z}`;
    let k = index.get(key);
    if (k === undefined) {
      k = vertices.length / 3;
      index.set(key, k);
      vertices.push(x, y, z);
    }
    faces[i] = k;
  }
  return { vertices: Float64Array.from(vertices), faces };
}
