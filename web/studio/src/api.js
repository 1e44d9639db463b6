// The studio's JSON API (compiler/studio/studio_routes.cpp), as the page calls it.
export async function api(method, path, body) {
  const init = { method, headers: {} };
  if (body !== undefined) {
    init.headers["Content-Type"] = "application/json";
    init.body = JSON.stringify(body);
  }
  const res = await fetch(path, init);
  const type = res.headers.get("Content-Type") || "";
  if (type.startsWith("application/json")) return { status: res.status, data: await res.json() };
  return { status: res.status, data: null, blob: await res.blob() };
}
