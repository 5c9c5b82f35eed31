/*
 * vendor_cad_api.h - C interface of the (fictional) "VC" vendor CAD kernel.
 *
 * This is the header a proprietary CAD SDK ships, in the style of CADfix's CFI interface
 * (opaque handles, integer status codes, out-parameters, one session per process/thread).
 * semimesh's `vendor` backend compiles against this header only; at link time either the real
 * SDK (libvendor_cad) or the fake used by the tests provides the symbols.
 *
 * Conventions (all functions):
 *  - Every function returns a vc_status; VC_OK (0) on success. On failure the out-parameters are
 *    left untouched and vc_error_message() describes the failure in words.
 *  - Entities are identified by vc_entity ids: 1-based, unique within a model across all entity
 *    types, stable for the model's lifetime. 0 (VC_NULL_ENTITY) is never a valid entity.
 *  - Indices passed to "get by index" functions are 1-based: 1..count.
 *  - Points and vectors are double[3] (x, y, z) in the model's unit (vc_model_units).
 *    Surface parameters are double[2] (u, v).
 *  - Optional out-parameters may be NULL when the caller does not need them.
 *  - Thread safety: a session and the models loaded in it must be used by one thread at a time.
 *    Distinct sessions are independent.
 */
#ifndef VENDOR_CAD_API_H
#define VENDOR_CAD_API_H

#include <stddef.h>
#include <stdint.h>

/* Symbols the library exports (it may build with hidden visibility for everything else). */
#if defined(__GNUC__)
#define VC_API __attribute__((visibility("default")))
#else
#define VC_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- handles and ids ---------------------------------------------------------------------- */

typedef struct vc_session_s* vc_session; /* a kernel session; owns loaded models */
typedef struct vc_model_s* vc_model;     /* a loaded model (its bodies, faces, edges, vertices) */
typedef int64_t vc_entity;               /* entity id within a model, 1-based */

#define VC_NULL_ENTITY ((vc_entity)0)
#define VC_API_VERSION 4  /* 4: vc_face_periodicity, vc_edge_degenerate */

/* ---- status codes ------------------------------------------------------------------------- */

typedef int vc_status;
enum {
  VC_OK = 0,
  VC_ERR_FILE_NOT_FOUND = 1,  /* the path does not exist or cannot be opened */
  VC_ERR_BAD_FILE = 2,        /* the file exists but its content cannot be read as a model */
  VC_ERR_BAD_HANDLE = 3,      /* NULL/closed session or model, or an entity id the model lacks */
  VC_ERR_BAD_PARAM = 4,       /* a malformed argument: NULL pointer, NaN, bad option value */
  VC_ERR_OUT_OF_RANGE = 5,    /* an index or a parameter outside its valid range */
  VC_ERR_UNKNOWN_OPTION = 6,  /* a load option name the kernel does not know */
  VC_ERR_WRONG_TYPE = 7,      /* the entity exists but is of another type (edge given for face) */
  VC_ERR_EMPTY_MODEL = 8,     /* the model loaded but holds no faces */
  VC_ERR_NOT_CONVERGED = 9,   /* an iterative query (projection) did not meet its tolerance */
  VC_ERR_INTERNAL = 10        /* any other kernel failure */
};

/* ---- enumerations ------------------------------------------------------------------------- */

typedef enum vc_entity_type {
  VC_TYPE_BODY = 1,   /* a solid or sheet: a set of faces, each with a sense */
  VC_TYPE_FACE = 2,   /* a trimmed surface */
  VC_TYPE_EDGE = 3,   /* a bounded curve between two vertices */
  VC_TYPE_VERTEX = 4  /* a point */
} vc_entity_type;

/* Orientation of a use of an entity relative to the entity's own parametrisation. */
typedef enum vc_sense {
  VC_SENSE_SAME = 1,     /* edge in a loop: walked from t0 to t1; face in a body: the natural normal
                            du x dv points out of the body's material */
  VC_SENSE_REVERSED = -1 /* the opposite */
} vc_sense;

typedef enum vc_unit {
  VC_UNIT_UNKNOWN = 0,
  VC_UNIT_METRE = 1,
  VC_UNIT_MILLIMETRE = 2,
  VC_UNIT_CENTIMETRE = 3,
  VC_UNIT_INCH = 4,
  VC_UNIT_FOOT = 5
} vc_unit;

/* Geometry carried by a face or an edge. */
typedef enum vc_geometry_type {
  VC_GEOM_OTHER = 0,
  VC_GEOM_PLANE = 1,
  VC_GEOM_CYLINDER = 2,
  VC_GEOM_NURBS_SURFACE = 3,
  VC_GEOM_ANALYTIC_SURFACE = 4, /* closed-form procedural surface */
  VC_GEOM_LINE = 11,
  VC_GEOM_CIRCLE = 12,
  VC_GEOM_NURBS_CURVE = 13,
  VC_GEOM_ANALYTIC_CURVE = 14   /* closed-form procedural curve */
} vc_geometry_type;

/* ---- library and session ------------------------------------------------------------------ */

/* Version of the API the library implements (compare with VC_API_VERSION). Never fails. */
VC_API int vc_api_version(void);

/* Short symbolic name of a status code ("VC_ERR_BAD_FILE"); "VC_UNKNOWN_STATUS" for others.
 * The string is static. Never fails. */
VC_API const char* vc_status_name(vc_status status);

/* Opens a kernel session. *session receives the handle; close it with vc_session_close. */
VC_API vc_status vc_session_open(vc_session* session);

/* Closes a session and frees every model still loaded in it. NULL is accepted (no-op). */
VC_API vc_status vc_session_close(vc_session session);

/* Human-readable description of the last failed call made in this session ("" if none).
 * The string is owned by the session and valid until its next call. NULL session: a static
 * message saying so. */
VC_API const char* vc_error_message(vc_session session);

/* ---- models ------------------------------------------------------------------------------- */

/* Loads a model from `path` into the session.
 *   path:    a model file; the kernel's file formats are its own business.
 *   options: load options as "key=value" pairs separated by ';' (e.g. "units=mm;heal=1"); NULL
 *            or "" for none. Unknown keys fail with VC_ERR_UNKNOWN_OPTION, bad values with
 *            VC_ERR_BAD_PARAM.
 *   model:   receives the handle; free it with vc_model_free (or close the session).
 * Errors: VC_ERR_FILE_NOT_FOUND, VC_ERR_BAD_FILE, VC_ERR_UNKNOWN_OPTION, VC_ERR_BAD_PARAM,
 *         VC_ERR_EMPTY_MODEL, VC_ERR_BAD_HANDLE (session). */
VC_API vc_status vc_model_load(vc_session session, const char* path, const char* options, vc_model* model);

/* Frees a model and all its entities. NULL is accepted (no-op). */
VC_API vc_status vc_model_free(vc_model model);

/* Unit of every coordinate of the model. */
VC_API vc_status vc_model_units(vc_model model, vc_unit* unit);

/* Geometric tolerance of the model (in its unit): points closer than this are the same. */
VC_API vc_status vc_model_tolerance(vc_model model, double* tolerance);

/* Number of entities of one type in the model. */
VC_API vc_status vc_model_entity_count(vc_model model, vc_entity_type type, int* count);

/* The index-th entity (1-based, 1..count) of a type. The order is stable for the model. */
VC_API vc_status vc_model_entity(vc_model model, vc_entity_type type, int index, vc_entity* entity);

/* ---- any entity --------------------------------------------------------------------------- */

/* Type of an entity. */
VC_API vc_status vc_entity_get_type(vc_model model, vc_entity entity, vc_entity_type* type);

/* Name of an entity ("" if it has none). The string is owned by the model and valid until
 * vc_model_free. */
VC_API vc_status vc_entity_name(vc_model model, vc_entity entity, const char** name);

/* ---- bodies ------------------------------------------------------------------------------- */

/* Number of faces bounding a body. */
VC_API vc_status vc_body_face_count(vc_model model, vc_entity body, int* count);

/* The index-th face (1-based) of a body and its sense in that body: VC_SENSE_SAME when the face's
 * natural normal du x dv points out of the body's material, VC_SENSE_REVERSED otherwise. */
VC_API vc_status vc_body_face(vc_model model, vc_entity body, int index, vc_entity* face, vc_sense* sense);

/* ---- faces -------------------------------------------------------------------------------- */

/* Geometry type of a face. */
VC_API vc_status vc_face_geometry(vc_model model, vc_entity face, vc_geometry_type* type);

/* Parameter box of the face: uv_min[2] = (u0, v0), uv_max[2] = (u1, v1). The trimming loops lie
 * inside it. */
VC_API vc_status vc_face_range(vc_model model, vc_entity face, double uv_min[2], double uv_max[2]);

/* Point and partial derivatives at uv[2]. Each output is a double[3] and may be NULL:
 * p = S, du = dS/du, dv = dS/dv, duu = d2S/du2, duv = d2S/dudv, dvv = d2S/dv2.
 * Errors: VC_ERR_OUT_OF_RANGE when uv lies outside the parameter box by more than 1e-6 of its
 *         size; VC_ERR_BAD_PARAM for a NaN parameter. */
VC_API vc_status vc_face_eval(vc_model model, vc_entity face, const double uv[2], double p[3], double du[3],
                       double dv[3], double duu[3], double duv[3], double dvv[3]);

/* Unit natural normal (du x dv normalised) at uv[2]; independent of the face's sense in a body.
 * Errors as vc_face_eval; VC_ERR_INTERNAL at a degenerate point where du x dv vanishes. */
VC_API vc_status vc_face_normal(vc_model model, vc_entity face, const double uv[2], double normal[3]);

/* Periodicity of the face's parameters: periodic[i] = 1 when S closes on itself along parameter i
 * (0: u, 1: v), S(.. + period[i] ..) = S; then period[i] is that period, else 0. A face on a
 * periodic surface is usually bounded by a seam edge its loop uses twice, once each way. */
VC_API vc_status vc_face_periodicity(vc_model model, vc_entity face, int periodic[2], double period[2]);

/* Whether uv[2] lies inside the trimmed face (1) or outside it (0); on the boundary is inside. */
VC_API vc_status vc_face_inside(vc_model model, vc_entity face, const double uv[2], int* inside);

/* Closest point of the face to x[3].
 *   uv_guess: a starting parameter pair, or NULL to let the kernel find one.
 *   uv[2], p[3], distance: the parameters, the point and |x - p| found (p, distance may be NULL).
 *   converged: 1 when the solver met its tolerance, 0 when it returns its best iterate (may be
 *              NULL). A non-converged projection is not an error.
 *   inside: 1 when uv lies inside the trimmed face (may be NULL). */
VC_API vc_status vc_face_project(vc_model model, vc_entity face, const double x[3], const double* uv_guess,
                          double uv[2], double p[3], double* distance, int* converged, int* inside);

/* Number of boundary loops of a face. Loop 1 is the outer loop. */
VC_API vc_status vc_face_loop_count(vc_model model, vc_entity face, int* count);

/* Number of edge uses in the loop-th loop (1-based) of a face. */
VC_API vc_status vc_face_loop_size(vc_model model, vc_entity face, int loop, int* count);

/* The index-th edge use (1-based) of the loop-th loop of a face. Loops run counter-clockwise
 * around the face's NATURAL normal du x dv (whatever its sense in a body); `sense` says whether
 * the loop walks the edge from its t0 end to its t1 end (VC_SENSE_SAME) or back. */
VC_API vc_status vc_face_loop_edge(vc_model model, vc_entity face, int loop, int index, vc_entity* edge, vc_sense* sense);

/* ---- edges -------------------------------------------------------------------------------- */

/* Geometry type of an edge. */
VC_API vc_status vc_edge_geometry(vc_model model, vc_entity edge, vc_geometry_type* type);

/* Parameter range [t0, t1] of the edge, t0 < t1. */
VC_API vc_status vc_edge_range(vc_model model, vc_entity edge, double* t0, double* t1);

/* Point, first and second derivative at t; each a double[3], each may be NULL.
 * Errors: VC_ERR_OUT_OF_RANGE when t lies outside [t0, t1] by more than 1e-6 of its length;
 *         VC_ERR_BAD_PARAM for a NaN parameter. */
VC_API vc_status vc_edge_eval(vc_model model, vc_entity edge, double t, double p[3], double d1[3], double d2[3]);

/* Closest point of the edge to x[3], with t clamped to [t0, t1].
 *   t_guess: a starting parameter, or NULL to let the kernel find one.
 *   t, p[3], distance, converged: as vc_face_project (p, distance, converged may be NULL). */
VC_API vc_status vc_edge_project(vc_model model, vc_entity edge, const double x[3], const double* t_guess, double* t,
                          double p[3], double* distance, int* converged);

/* Whether an edge is degenerate (1) or not (0): a single point walked over [t0, t1], the pole
 * of the face that uses it (the apex of a cone, the nose of a body of revolution). Its derivatives
 * are zero and its two end vertices are the same. */
VC_API vc_status vc_edge_degenerate(vc_model model, vc_entity edge, int* degenerate);

/* End vertices of an edge: `start` at t0, `end` at t1 (equal for a closed edge). */
VC_API vc_status vc_edge_vertices(vc_model model, vc_entity edge, vc_entity* start, vc_entity* end);

/* ---- vertices ----------------------------------------------------------------------------- */

/* Position of a vertex, p[3]. */
VC_API vc_status vc_vertex_point(vc_model model, vc_entity vertex, double p[3]);

#ifdef __cplusplus
}
#endif

#endif /* VENDOR_CAD_API_H */
