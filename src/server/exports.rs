//! Export jobs over HTTP: the batch exports of [`crate::export`] (`strata export` run locally)
//! run in the background on the server's [`super::jobs::Jobs`] queue.
//!
//! | route | who | answer |
//! |---|---|---|
//! | `POST /v1/worlds/{id}/exports` `{lod, region, products, formats?, v?, shard?}` | edit | 202 `{job, world, version, status, total, max_bytes, status_url, events_url, download_url}` |
//! | `GET /v1/jobs/{job}` | read on the job's world | `{id, world, version, shard, status, done, total, error?, download_url?}` |
//! | `GET /v1/jobs/{job}/events` | read on the job's world | `text/event-stream`: `progress`, then `done` or `failed` |
//! | `GET /v1/jobs/{job}/archive` | read on the job's world | the tar (`application/x-tar`); 409 before it is done |
//!
//! `region` is `[x0, z0, x1, z1]` in tile coordinates at `lod`, `x1` and `z1` exclusive (as
//! `strata export --region`); `v` defaults to the latest version; `shard` is `"i/N"` counted
//! from 1. The archive is the one `strata export` writes for the same seed, world settings and
//! arguments, byte for byte. Spec errors are 400 `invalid_export` (or `bad_body` for a body of
//! the wrong shape) whose `field` is a JSON pointer into the body (`/lod`, `/region/2`,
//! `/formats`, …). Queue limits: [`super::jobs`].
//!
//! Events: each is `event: <name>` with one JSON `data:` line. `progress` `{status, done,
//! total}` is sent first with the current state (so a late client catches up), then whenever
//! the state changes (tile progress is published at most every
//! [`super::jobs::PROGRESS_INTERVAL`], plus the final count); the stream ends with `done`
//! `{done, total, download_url}`, `failed` `{done, total, error}` or, for a job whose archive
//! has expired, `expired` `{done, total}`.
//!
//! Replicas ([`super::jobs::ledger`]): the `GET` routes answer for any job of the store, not
//! only this process's; another replica's job is read from the store (its events polled every
//! [`REMOTE_POLL`]) and its archive from the shared directory. The disk budgets and the queue
//! limit are counted in the store, over every replica's jobs, and any replica expires any job's
//! archive ([`super::jobs::quota`]).
//!
//! Disk budgets ([`super::jobs::quota`]): a job whose archive may exceed a budget is 400
//! `export_too_large` (field `/region`); one that does not fit beside the archives already held
//! is 429 `export_quota_exceeded` (field: the budget's name, `Retry-After`); an expired job's
//! archive is 410 `job_expired`.

use super::error::{code, AppError};
use super::http::{authorize, authorized_body, json_response, store_error};
use super::jobs::{valid_job_id, Job, Progress, Status, SubmitError};
use super::route_table::RouteTable;
use super::AppState;
use crate::export::{ExportSpec, Product, Shard};
use crate::store::{Role, StoreError};
use axum::body::{Body, Bytes};
use axum::extract::{Path, State};
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::response::sse::{Event, KeepAlive, Sse};
use axum::response::{IntoResponse, Response};
use serde::Deserialize;
use serde_json::{json, Value};
use std::collections::VecDeque;
use std::convert::Infallible;
use std::io::Read;
use std::sync::Arc;
use tokio::sync::{mpsc, watch};

/// Bytes per chunk of an archive download.
const ARCHIVE_CHUNK: usize = 64 << 10;

/// The routes of this module (merged into the service's router).
pub(super) fn routes() -> RouteTable {
    RouteTable::new()
        .post("/v1/worlds/{id}/exports", create)
        .get("/v1/jobs/{job}", status)
        .get("/v1/jobs/{job}/events", events)
        .get("/v1/jobs/{job}/archive", archive)
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ExportBody {
    lod: u32,
    region: [i64; 4],
    products: Vec<Product>,
    #[serde(default)]
    formats: Vec<String>,
    #[serde(default)]
    v: Option<u64>,
    #[serde(default)]
    shard: Option<String>,
    #[serde(default)]
    ptex_res: Option<u32>,
}

fn invalid(field: &'static str, message: impl Into<String>) -> AppError {
    AppError::bad_request(code::INVALID_EXPORT, field, message)
}

/// The body field an [`ExportSpec`] field comes from.
fn pointer(spec_field: &str) -> &'static str {
    match spec_field {
        "lod" => "/lod",
        "x0" => "/region/0",
        "z0" => "/region/1",
        "x1" => "/region/2",
        "z1" => "/region/3",
        "products" => "/products",
        "formats" => "/formats",
        "ptex_res" => "/ptex_res",
        _ => "body",
    }
}

/// The first index of a repeated item.
fn repeated<T: PartialEq>(items: &[T]) -> Option<usize> {
    (1..items.len()).find(|&i| items[..i].contains(&items[i]))
}

fn urls(job: &str) -> (String, String, String) {
    (
        format!("/v1/jobs/{job}"),
        format!("/v1/jobs/{job}/events"),
        format!("/v1/jobs/{job}/archive"),
    )
}

/// `POST /v1/worlds/{id}/exports`: needs the edit role, public world or not, since an export
/// writes to the server's disk.
async fn create(
    _charge: super::rate_limit::Charge,
    State(st): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
    body: Bytes,
) -> Result<Response, AppError> {
    let (meta, req): (_, ExportBody) =
        authorized_body(&st, &headers, &id, Role::Edit, &body).await?;
    let version = match req.v {
        None => meta.version,
        Some(0) => {
            return Err(AppError::bad_request(
                code::BAD_VERSION,
                "/v",
                "v must be a version number (a positive integer)",
            ))
        }
        Some(v) if v > meta.version => {
            return Err(store_error(StoreError::VersionNotFound {
                version: v,
                latest: meta.version,
            })
            .with_field("/v"))
        }
        Some(v) => v,
    };
    let shard = match &req.shard {
        None => Shard::WHOLE,
        Some(s) => Shard::parse(s).map_err(|e| invalid("/shard", e))?,
    };
    if let Some(i) = repeated(&req.products) {
        return Err(invalid(
            "/products",
            format!("products[{i}] is named twice"),
        ));
    }
    if let Some(i) = repeated(&req.formats) {
        return Err(invalid("/formats", format!("formats[{i}] is named twice")));
    }
    let [x0, z0, x1, z1] = req.region;
    let spec = ExportSpec {
        lod: req.lod,
        x0,
        z0,
        x1,
        z1,
        products: req.products,
        formats: req.formats,
        ptex_res: req.ptex_res,
    };
    let view = st.worlds.view(&meta, version).await?;
    let plan = view.plan.clone();
    spec.validate(&plan)
        .map_err(|e| invalid(pointer(e.field), e.message))?;
    // The elements the exported tiles meet, solved now (cached), so the archive shows the edits.
    let edits = view.edits_over(&st, &spec.keys(shard)).await;
    let job = match st
        .jobs
        .submit_shared(&meta.id, version, plan, edits, spec, shard)
        .await
    {
        Ok(job) => job,
        Err(e @ SubmitError::TooMany { .. }) => {
            let mut res = AppError::new(
                StatusCode::TOO_MANY_REQUESTS,
                code::TOO_MANY_JOBS,
                e.to_string(),
            )
            .into_response();
            res.headers_mut()
                .insert(header::RETRY_AFTER, HeaderValue::from_static("5"));
            return Ok(res);
        }
        Err(e @ SubmitError::TooLarge { .. }) => {
            return Err(AppError::bad_request(
                code::EXPORT_TOO_LARGE,
                "/region",
                e.to_string(),
            ))
        }
        Err(
            ref e @ SubmitError::OverQuota {
                budget,
                retry_after_s,
                ..
            },
        ) => {
            return Err(AppError::new(
                StatusCode::TOO_MANY_REQUESTS,
                code::EXPORT_QUOTA_EXCEEDED,
                e.to_string(),
            )
            .with_field(budget.name())
            .with_retry_after(retry_after_s))
        }
        Err(e @ SubmitError::Random(_)) => {
            tracing::error!("export job: {e}");
            return Err(AppError::internal("cannot draw a job id"));
        }
        Err(e @ SubmitError::Store(_)) => {
            tracing::error!("export job: {e}");
            return Err(AppError::internal("the export job cannot be stored"));
        }
    };
    let (status_url, events_url, download_url) = urls(&job.id);
    let p = job.progress();
    let mut res = json_response(
        StatusCode::ACCEPTED,
        json!({
            "job": job.id,
            "world": job.world,
            "version": job.version,
            "shard": shard_text(job.shard),
            "status": p.status,
            "total": p.total,
            "max_bytes": job.reserved,
            "status_url": status_url,
            "events_url": events_url,
            "download_url": download_url,
        }),
        "no-store",
    );
    if let Ok(v) = HeaderValue::from_str(&status_url) {
        res.headers_mut().insert(header::LOCATION, v);
    }
    Ok(res)
}

fn shard_text(s: Shard) -> String {
    format!("{}/{}", s.index + 1, s.count)
}

fn job_not_found(id: &str) -> AppError {
    AppError::new(
        StatusCode::NOT_FOUND,
        code::JOB_NOT_FOUND,
        format!("no export job {:?}", super::error::truncate(id, 64)),
    )
    .with_field("id")
}

/// The job `id`, after checking that the caller may read its world: this process's, or
/// another replica's as the store has it (then `true`).
async fn find(st: &AppState, headers: &HeaderMap, id: &str) -> Result<(Arc<Job>, bool), AppError> {
    if !valid_job_id(id) {
        return Err(job_not_found(id));
    }
    let found = match (st.jobs.get(id), st.jobs.ledger()) {
        (Some(job), _) => Some((job, false)),
        (None, Some(ledger)) => ledger
            .store
            .job(id)
            .await
            .map_err(store_error)?
            .and_then(|r| st.jobs.remote(&r))
            .map(|job| (job, true)),
        (None, None) => None,
    };
    let (job, remote) = found.ok_or_else(|| job_not_found(id))?;
    authorize(st, headers, &job.world, Role::Read).await?;
    Ok((job, remote))
}

/// How often the events of another replica's job are read from the store.
const REMOTE_POLL: std::time::Duration = std::time::Duration::from_millis(250);

/// Publishes the state of another replica's job, read from the store every [`REMOTE_POLL`],
/// until it ends or nobody follows it.
async fn poll_remote(st: AppState, job: Arc<Job>) {
    let Some(ledger) = st.jobs.ledger().cloned() else {
        return;
    };
    while !job.progress().status.is_finished() && job.followers() > 0 {
        tokio::time::sleep(REMOTE_POLL).await;
        match ledger.store.job(&job.id).await {
            Ok(Some(r)) => job.publish(super::jobs::ledger::progress_of(&r)),
            Ok(None) => return,
            Err(e) => tracing::warn!(job = %job.id, "cannot read the export job: {e}"),
        }
    }
}

/// `GET /v1/jobs/{job}`.
async fn status(
    State(st): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let (job, _) = find(&st, &headers, &id).await?;
    let p = job.progress();
    let mut doc = json!({
        "id": job.id,
        "world": job.world,
        "version": job.version,
        "shard": shard_text(job.shard),
        "status": p.status,
        "done": p.done,
        "total": p.total,
    });
    if let Some(e) = &p.error {
        doc["error"] = json!(e);
    }
    if p.status == Status::Done {
        doc["download_url"] = json!(urls(&job.id).2);
    }
    Ok(json_response(StatusCode::OK, doc, "no-store"))
}

/// Turns a job's state changes into server-sent events.
struct Follow {
    job: Arc<Job>,
    rx: watch::Receiver<Progress>,
    last: Option<(Status, usize, usize)>,
    pending: VecDeque<Event>,
    end: bool,
}

fn event(name: &str, data: &Value) -> Event {
    Event::default().event(name).data(data.to_string())
}

impl Follow {
    fn push(&mut self, p: &Progress) {
        let now = (p.status, p.done, p.total);
        let counts_changed = self
            .last
            .is_none_or(|(_, d, t)| (d, t) != (p.done, p.total));
        if counts_changed || (!p.status.is_finished() && self.last != Some(now)) {
            self.last = Some(now);
            self.pending.push_back(event(
                "progress",
                &json!({ "status": p.status, "done": p.done, "total": p.total }),
            ));
        }
        match p.status {
            Status::Done => {
                self.pending.push_back(event(
                    "done",
                    &json!({ "done": p.done, "total": p.total,
                             "download_url": urls(&self.job.id).2 }),
                ));
                self.end = true;
            }
            Status::Failed => {
                self.pending.push_back(event(
                    "failed",
                    &json!({ "done": p.done, "total": p.total,
                             "error": p.error.as_deref().unwrap_or("failed") }),
                ));
                self.end = true;
            }
            Status::Expired => {
                self.pending.push_back(event(
                    "expired",
                    &json!({ "done": p.done, "total": p.total }),
                ));
                self.end = true;
            }
            Status::Queued | Status::Running => {}
        }
    }

    async fn next(mut self) -> Option<(Result<Event, Infallible>, Self)> {
        loop {
            if let Some(e) = self.pending.pop_front() {
                return Some((Ok(e), self));
            }
            if self.end {
                return None;
            }
            let p = self.rx.borrow_and_update().clone();
            self.push(&p);
            // `changed` fails only when the job is gone, and `self.job` keeps it alive.
            if self.pending.is_empty() && self.rx.changed().await.is_err() {
                self.end = true;
            }
        }
    }
}

/// `GET /v1/jobs/{job}/events`.
async fn events(
    State(st): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let (job, remote) = find(&st, &headers, &id).await?;
    let rx = job.subscribe();
    if remote {
        tokio::spawn(poll_remote(st.clone(), job.clone()));
    }
    let follow = Follow {
        rx,
        job,
        last: None,
        pending: VecDeque::new(),
        end: false,
    };
    let stream = futures::stream::unfold(follow, Follow::next);
    let mut res = Sse::new(stream)
        .keep_alive(KeepAlive::default())
        .into_response();
    let h = res.headers_mut();
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    h.insert("x-accel-buffering", HeaderValue::from_static("no"));
    Ok(res)
}

/// `GET /v1/jobs/{job}/archive`.
async fn archive(
    State(st): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let (job, _) = find(&st, &headers, &id).await?;
    let p = job.progress();
    let Some(path) = job.archive().map(|p| p.to_path_buf()) else {
        return Err(match p.status {
            Status::Expired => AppError::new(
                StatusCode::GONE,
                code::JOB_EXPIRED,
                format!(
                    "the archive of export job {} expired {} s after it was done and was deleted",
                    job.id,
                    st.jobs.limits().max_age.as_secs()
                ),
            ),
            Status::Failed => AppError::new(
                StatusCode::CONFLICT,
                code::JOB_FAILED,
                format!(
                    "export job {} failed: {}",
                    job.id,
                    p.error.as_deref().unwrap_or("unknown error")
                ),
            ),
            _ => AppError::new(
                StatusCode::CONFLICT,
                code::JOB_NOT_DONE,
                format!(
                    "export job {} is {} ({} of {} tiles); its archive is not ready",
                    job.id,
                    p.status.as_str(),
                    p.done,
                    p.total
                ),
            ),
        });
    };
    // Open before answering: a job forgotten after this point still streams its archive.
    let opened = tokio::task::spawn_blocking(move || {
        let file = std::fs::File::open(&path)?;
        let len = file.metadata()?.len();
        Ok::<_, std::io::Error>((file, len))
    })
    .await
    .map_err(|e| AppError::internal(format!("opening the archive failed: {e}")))?;
    let (mut file, len) = opened.map_err(|e| {
        if e.kind() == std::io::ErrorKind::NotFound {
            // Forgotten (and deleted) since it was looked up.
            return job_not_found(&job.id);
        }
        tracing::error!(job = %job.id, "cannot open the archive: {e}");
        AppError::internal("the archive cannot be read")
    })?;
    let (tx, rx) = mpsc::channel::<std::io::Result<Bytes>>(4);
    tokio::task::spawn_blocking(move || loop {
        let mut buf = vec![0u8; ARCHIVE_CHUNK];
        let chunk = match file.read(&mut buf) {
            Ok(0) => return,
            Ok(n) => {
                buf.truncate(n);
                Ok(Bytes::from(buf))
            }
            Err(e) => Err(e),
        };
        let failed = chunk.is_err();
        if tx.blocking_send(chunk).is_err() || failed {
            return;
        }
    });
    let body = Body::from_stream(futures::stream::unfold(rx, |mut rx| async move {
        rx.recv().await.map(|chunk| (chunk, rx))
    }));
    let mut name = format!("strata-{}-v{}", job.world, job.version);
    if job.shard.count > 1 {
        name.push_str(&format!(
            "-shard-{}-of-{}",
            job.shard.index + 1,
            job.shard.count
        ));
    }
    let mut res = (StatusCode::OK, body).into_response();
    let h = res.headers_mut();
    h.insert(
        header::CONTENT_TYPE,
        HeaderValue::from_static("application/x-tar"),
    );
    h.insert(header::CONTENT_LENGTH, HeaderValue::from(len));
    if let Ok(v) = HeaderValue::from_str(&format!("attachment; filename=\"{name}.tar\"")) {
        h.insert(header::CONTENT_DISPOSITION, v);
    }
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    Ok(res)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spec_fields_map_to_body_pointers() {
        assert_eq!(pointer("x1"), "/region/2");
        assert_eq!(pointer("formats"), "/formats");
        assert_eq!(repeated(&["bin", "png", "bin"]), Some(2));
        assert_eq!(repeated(&["bin", "png"]), None);
        assert_eq!(repeated::<u8>(&[]), None);
    }
}
