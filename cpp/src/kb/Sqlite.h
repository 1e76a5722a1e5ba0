#pragma once
// SQLite plumbing shared by the knowledge-base files: prepared statements, transactions, and
// the one place result codes become messages. Internal to cpp/src/kb.
#include <aeronc/core/Error.h>

#include <sqlite3.h>

#include <climits>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace aeronc::kb::detail {

inline std::string quoted(const std::string& s) { return "'" + s + "'"; }

// The one place sqlite result codes become messages.
[[noreturn]] inline void fail(sqlite3* db, int rc, const std::string& path, const std::string& what) {
    const std::string detail = db ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
    const int primary = rc & 0xff;
    std::ostringstream m;
    m << "knowledge base " << quoted(path) << ": ";
    if (primary == SQLITE_BUSY || primary == SQLITE_LOCKED)
        m << "the database is locked by another program or session (" << detail << ") while " << what
          << "; close the other program and retry";
    else if (primary == SQLITE_NOTADB)
        m << "file is not a database; it is corrupt or some other kind of file (sqlite: " << detail << ")";
    else if (primary == SQLITE_CORRUPT)
        m << "the database file is corrupt (" << detail << ")";
    else if (primary == SQLITE_CANTOPEN)
        m << "cannot open the file (" << detail << ")";
    else if (primary == SQLITE_READONLY || primary == SQLITE_PERM)
        m << "the file is read-only (" << detail << ") while " << what;
    else
        m << what << " failed: " << detail;
    throw inputError(m.str());
}

class Statement {
public:
    Statement(sqlite3* db, const std::string& path, const char* sql) : db_(db), path_(path) {
        const int rc = sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr);
        if (rc != SQLITE_OK) fail(db_, rc, path_, "preparing a query");
    }
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;
    ~Statement() { sqlite3_finalize(stmt_); }

    Statement& bind(int i, const std::string& v) {
        check(sqlite3_bind_text(stmt_, i, v.c_str(), static_cast<int>(v.size()), SQLITE_TRANSIENT));
        return *this;
    }
    Statement& bindNull(int i) { check(sqlite3_bind_null(stmt_, i)); return *this; }
    Statement& bindInt64(int i, long long v) { check(sqlite3_bind_int64(stmt_, i, v)); return *this; }
    sqlite3_stmt* raw() const { return stmt_; }
    Statement& bind(int i, double v) { check(sqlite3_bind_double(stmt_, i, v)); return *this; }
    Statement& bind(int i, int v) { check(sqlite3_bind_int(stmt_, i, v)); return *this; }
    Statement& bind(int i, std::optional<double> v) {
        check(v ? sqlite3_bind_double(stmt_, i, *v) : sqlite3_bind_null(stmt_, i));
        return *this;
    }
    // Returns true while there is a row; throws on an error with `what` in the message.
    bool step(const std::string& what = "reading") {
        const int rc = sqlite3_step(stmt_);
        if (rc == SQLITE_ROW) return true;
        if (rc == SQLITE_DONE) return false;
        lastError_ = sqlite3_extended_errcode(db_);
        fail(db_, lastError_, path_, what);
    }
    // Like step() but returns the result code instead of throwing (for constraint mapping).
    int tryStep() { return sqlite3_step(stmt_); }
    void reset() { sqlite3_reset(stmt_); sqlite3_clear_bindings(stmt_); }

    std::string text(int c) const {
        const unsigned char* p = sqlite3_column_text(stmt_, c);
        return p ? reinterpret_cast<const char*>(p) : std::string();
    }
    // What the row is, for messages about its cells ("tool 'EM-F2'").
    void about(std::string row) { row_ = std::move(row); }
    // A cell of a REAL column: a finite number. SQLite keeps whatever a program stored there
    // (text, NULL, a blob, an overflow read as inf), and a CHECK (x > 0) lets text through, so
    // anything else is an error naming the row and the column, never 0.0 or inf.
    double real(int c) const {
        const int type = sqlite3_column_type(stmt_, c);
        if (type != SQLITE_INTEGER && type != SQLITE_FLOAT) notANumber(c, "a number");
        const double v = sqlite3_column_double(stmt_, c);
        if (!std::isfinite(v)) notANumber(c, "a finite number");
        return v;
    }
    // A cell of an INTEGER column: a whole number that fits an int.
    int integer(int c) const {
        const int type = sqlite3_column_type(stmt_, c);
        if (type == SQLITE_INTEGER) {
            const long long v = sqlite3_column_int64(stmt_, c);
            if (v >= INT_MIN && v <= INT_MAX) return static_cast<int>(v);
        } else if (type == SQLITE_FLOAT) {
            const double v = sqlite3_column_double(stmt_, c);
            if (v == std::floor(v) && v >= INT_MIN && v <= INT_MAX) return static_cast<int>(v);
        }
        notANumber(c, "a whole number from " + std::to_string(INT_MIN) + " to " + std::to_string(INT_MAX));
    }
    bool isNull(int c) const { return sqlite3_column_type(stmt_, c) == SQLITE_NULL; }
    std::optional<double> optReal(int c) const {
        if (sqlite3_column_type(stmt_, c) == SQLITE_NULL) return std::nullopt;
        return real(c);
    }

private:
    void check(int rc) { if (rc != SQLITE_OK) fail(db_, rc, path_, "binding a value"); }
    [[noreturn]] void notANumber(int c, const std::string& expected) const {
        std::string held;
        switch (sqlite3_column_type(stmt_, c)) {
            case SQLITE_NULL: held = "NULL"; break;
            case SQLITE_BLOB: held = "binary data"; break;
            case SQLITE_TEXT: {
                std::string t = text(c);
                if (t.size() > 40) t = t.substr(0, 40) + "...";
                held = "the text " + quoted(t);
                break;
            }
            default: held = text(c);
        }
        const char* name = sqlite3_column_name(stmt_, c);
        throw inputError("knowledge base " + quoted(path_) + ": " + (row_.empty() ? "" : row_ + ": ") + "column " +
                         (name ? name : "?") + " holds " + held + ", not " + expected);
    }
    sqlite3* db_;
    const std::string& path_;
    sqlite3_stmt* stmt_ = nullptr;
    int lastError_ = 0;
    std::string row_;
};

inline void exec(sqlite3* db, const std::string& path, const std::string& sql, const std::string& what) {
    char* err = nullptr;
    const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err);
    if (rc == SQLITE_OK) return;
    std::string detail = err ? err : sqlite3_errmsg(db);
    sqlite3_free(err);
    const int primary = rc & 0xff;
    if (primary == SQLITE_BUSY || primary == SQLITE_LOCKED || primary == SQLITE_NOTADB ||
        primary == SQLITE_CORRUPT || primary == SQLITE_READONLY)
        fail(db, rc, path, what);
    throw inputError("knowledge base " + quoted(path) + ": " + what + " failed: " + detail);
}

// BEGIN IMMEDIATE takes the write lock up front, so a locked file is reported before any
// change; the destructor rolls back unless commit() ran.
class Transaction {
public:
    Transaction(sqlite3* db, const std::string& path, const std::string& what) : db_(db), path_(path), what_(what) {
        exec(db_, path_, "BEGIN IMMEDIATE", what_);
    }
    Transaction(const Transaction&) = delete;
    Transaction& operator=(const Transaction&) = delete;
    ~Transaction() {
        if (!done_) sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    }
    void commit() {
        exec(db_, path_, "COMMIT", what_);
        done_ = true;
    }

private:
    sqlite3* db_;
    const std::string& path_;
    std::string what_;
    bool done_ = false;
};


// A lookup that finds nothing may be looking at a damaged page (an index page emptied by a
// torn write hides its rows), so the file is checked before a row is called unknown. Throws
// "the database file is corrupt" when it is damaged.
inline void checkIntact(sqlite3* db, const std::string& path) {
    std::string verdict;
    sqlite3_stmt* s = nullptr;
    if (sqlite3_prepare_v2(db, "PRAGMA integrity_check(3)", -1, &s, nullptr) == SQLITE_OK) {
        int rc;
        while ((rc = sqlite3_step(s)) == SQLITE_ROW) {
            const unsigned char* t = sqlite3_column_text(s, 0);
            const std::string line = t ? reinterpret_cast<const char*>(t) : "";
            if (line != "ok") verdict += (verdict.empty() ? "" : "; ") + line;
        }
        if (rc != SQLITE_DONE && verdict.empty()) verdict = sqlite3_errmsg(db);
    } else {
        verdict = sqlite3_errmsg(db);
    }
    sqlite3_finalize(s);
    if (!verdict.empty())
        throw inputError("knowledge base " + quoted(path) + ": the database file is corrupt (" + verdict +
                         "); restore it from a backup");
}

// checkIntact(), then inputError(message): the row is really unknown.
[[noreturn]] inline void notFound(sqlite3* db, const std::string& path, const std::string& message) {
    checkIntact(db, path);
    throw inputError(message);
}

inline std::vector<std::string> names(sqlite3* db, const std::string& path, const char* sql) {
    Statement s(db, path, sql);
    std::vector<std::string> out;
    while (s.step()) out.push_back(s.text(0));
    return out;
}

inline std::string joined(const std::vector<std::string>& v) {
    std::string out;
    for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
    return out;
}


}  // namespace aeronc::kb::detail
