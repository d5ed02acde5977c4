// The deployment's own rules, on the rendered manifests of deploy/kubernetes (docs/deploy.md
// "Kubernetes"): one writer (a StatefulSet of one replica with --role=writer, its database on a
// volume claim template), query replicas without a database (--role=query, no --db), every
// clearsky container probed on /readyz and /healthz with requests and a memory limit, the token
// only as a mounted Secret file (--token-file, never --token or an environment variable), the
// drain within the grace period, an HPA and a PodDisruptionBudget for the replicas.
// Usage: node topology.js MANIFEST.yaml (js-yaml from NODE_PATH).
"use strict";
const fs = require("fs");
const yaml = require("js-yaml");

const docs = yaml.loadAll(fs.readFileSync(process.argv[2], "utf8")).filter((d) => d);
const failures = [];
const check = (ok, what) => {
  if (!ok) failures.push(what);
};
const of = (kind) => docs.filter((d) => d.kind === kind);
const argValue = (args, name) => {
  const a = args.find((x) => x.startsWith(`--${name}=`));
  return a === undefined ? undefined : a.slice(name.length + 3);
};

const writers = of("StatefulSet").filter((s) => s.metadata.name.includes("writer"));
check(writers.length === 1, "exactly one writer StatefulSet");
const queries = of("Deployment").filter((d) => d.metadata.name.includes("query"));
check(queries.length === 1, "exactly one query Deployment");

const podChecks = (workload, role) => {
  const spec = workload.spec.template.spec;
  const c = spec.containers.find((x) => x.name === "clearsky");
  check(c !== undefined, `${workload.metadata.name}: a clearsky container`);
  if (!c) return;
  const args = c.args || [];
  const name = workload.metadata.name;
  check(args[0] === "serve", `${name}: runs serve`);
  check(argValue(args, "role") === role, `${name}: --role=${role}`);
  check(!args.some((a) => a.startsWith("--token=") || a === "--token"), `${name}: no --token`);
  check(!(c.env || []).some((e) => e.name === "CLEARSKY_TOKEN"), `${name}: no CLEARSKY_TOKEN`);
  check(c.readinessProbe && c.readinessProbe.httpGet.path === "/readyz", `${name}: /readyz`);
  check(c.livenessProbe && c.livenessProbe.httpGet.path === "/healthz", `${name}: /healthz`);
  const r = c.resources || {};
  check(r.requests && r.requests.cpu && r.requests.memory, `${name}: cpu and memory requests`);
  check(r.limits && r.limits.memory, `${name}: a memory limit`);
  const drain = Number(argValue(args, "drain-delay") || 0) + Number(argValue(args, "drain-timeout") || 30);
  check(spec.terminationGracePeriodSeconds > drain, `${name}: grace period above the drain (${drain} s)`);
  check(c.securityContext && c.securityContext.readOnlyRootFilesystem === true, `${name}: read-only root`);
  check(spec.securityContext && spec.securityContext.runAsNonRoot === true, `${name}: non-root`);
  const cache = argValue(args, "cache-dir");
  const mount = (c.volumeMounts || []).find((m) => m.mountPath === cache);
  const volume = mount && spec.volumes.find((v) => v.name === mount.name);
  check(volume && volume.persistentVolumeClaim, `${name}: --cache-dir on the shared claim`);
  return { c, args, spec, name };
};

for (const w of writers) {
  check(w.spec.replicas === 1, "the writer has one replica");
  const p = podChecks(w, "writer");
  if (p) {
    const db = argValue(p.args, "db");
    check(db !== undefined, "the writer has --db");
    const claim = (w.spec.volumeClaimTemplates || []).map((t) => t.metadata.name);
    const mount = (p.c.volumeMounts || []).find((m) => db && db.startsWith(m.mountPath + "/"));
    check(mount && claim.includes(mount.name), "the writer's --db is on its volume claim template");
    const tokenFile = argValue(p.args, "token-file");
    const tokenMount = (p.c.volumeMounts || []).find((m) => tokenFile && tokenFile.startsWith(m.mountPath + "/"));
    const tokenVolume = tokenMount && p.spec.volumes.find((v) => v.name === tokenMount.name);
    check(tokenVolume && tokenVolume.secret, "the writer's --token-file is a mounted Secret");
  }
}
for (const q of queries) {
  const p = podChecks(q, "query");
  if (p) check(argValue(p.args, "db") === undefined, "query replicas have no --db");
}
const hpa = of("HorizontalPodAutoscaler");
check(hpa.length === 1 && hpa[0].spec.scaleTargetRef.name === (queries[0] || {}).metadata?.name,
      "an HPA scales the query Deployment");
check(hpa.length === 1 && hpa[0].spec.metrics.some((m) => m.resource && m.resource.name === "cpu"),
      "the HPA follows CPU");
check(of("PodDisruptionBudget").length === 1, "a PodDisruptionBudget");
check(of("Service").length >= 2, "Services for the writer and the replicas");

for (const f of failures) console.log(`FAIL ${f}`);
console.log(`topology: ${failures.length} rules broken`);
process.exit(failures.length ? 1 : 0);
