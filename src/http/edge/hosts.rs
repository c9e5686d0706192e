//! The `Host` check against DNS rebinding: a page from `evil.example` whose name
//! is made to resolve to 127.0.0.1 sends `Host: evil.example:8080`, so only
//! names the operator configured (and address literals, which no page can
//! rebind) are answered.

use axum::http::{header, HeaderMap, StatusCode, Uri};

use crate::http::error::ApiError;

/// Accepted `Host` values. By default: `localhost` and any address literal
/// (`127.0.0.1`, `[::1]`, the listen address, the machine's LAN address), with
/// any port (a port mapping or proxy may change it, and no page can rebind a
/// literal); `--allowed-hosts` adds names (`stand-pc` for any port,
/// `stand-pc:8080` for one); `*` turns the check off (behind a proxy that checks).
#[derive(Debug, Clone, Default)]
pub struct AllowedHosts {
    names: Vec<String>,
    any: bool,
}

impl AllowedHosts {
    /// From the comma-separated `--allowed-hosts` list.
    pub fn parse(list: &str) -> AllowedHosts {
        let mut hosts = AllowedHosts::default();
        for name in list.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            if name == "*" {
                hosts.any = true;
            } else {
                hosts.names.push(name.to_ascii_lowercase());
            }
        }
        hosts
    }

    /// [`AllowedHosts::parse`], refusing an entry that no `Host` header can
    /// equal, named with what is meant.
    pub fn try_parse(list: &str) -> Result<AllowedHosts, String> {
        for entry in list.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            if entry != "*" && !host_entry(entry) {
                return Err(format!(
                    "--allowed-hosts: '{entry}' is not a host name as a Host header gives it: \
                     a name or address with an optional port (`stand-pc`, `stand-pc:8080`, \
                     `[fd00::5]:8080`), no scheme or path; `*` for any"
                ));
            }
        }
        Ok(AllowedHosts::parse(list))
    }

    /// Whether `host` (`name`, `name:port`, `[v6]:port`) may be answered.
    pub fn allows(&self, host: &str) -> bool {
        if self.any {
            return true;
        }
        let host = host.trim().to_ascii_lowercase();
        let (name, _port) = split_port(&host);
        if self
            .names
            .iter()
            .any(|n| *n == host || ((!n.contains(':') || n.starts_with('[')) && *n == name))
        {
            return true;
        }
        name == "localhost" || literal_address(name)
    }

    /// `Err` is the 421 naming `Host` when the request's host is not allowed.
    pub fn check(&self, headers: &HeaderMap, uri: &Uri) -> Result<(), ApiError> {
        let host = headers
            .get(header::HOST)
            .and_then(|v| v.to_str().ok())
            .or_else(|| uri.authority().map(|a| a.as_str()));
        match host {
            Some(h) if self.allows(h) => Ok(()),
            Some(_) => Err(ApiError::new(
                StatusCode::MISDIRECTED_REQUEST,
                "host_not_allowed",
                "this service does not answer to that Host name; see --allowed-hosts",
            )
            .with_field("Host")),
            None => Err(ApiError::new(
                StatusCode::BAD_REQUEST,
                "missing_host",
                "the request has no Host header",
            )
            .with_field("Host")),
        }
    }
}

/// Whether `entry` can equal a `Host` header: a name (letters, digits, `-`,
/// `.`, `_`) or a bracketed IPv6 literal, then optionally `:port`.
fn host_entry(entry: &str) -> bool {
    let (name, port) = split_port(entry);
    let port_ok = match entry.len() - name.len() {
        0 => true,
        _ => port.is_some(),
    };
    let name_ok = if name.starts_with('[') {
        literal_address(name)
    } else {
        !name.is_empty()
            && name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || "-._".contains(c))
    };
    name_ok && port_ok
}

/// `127.0.0.1`, `[::1]` (brackets required for IPv6, as in a Host header).
fn literal_address(name: &str) -> bool {
    match name.strip_prefix('[').and_then(|n| n.strip_suffix(']')) {
        Some(v6) => v6.parse::<std::net::Ipv6Addr>().is_ok(),
        None => name.parse::<std::net::Ipv4Addr>().is_ok(),
    }
}

/// `("name", Some(port))` from `name:port`; IPv6 literals keep their brackets.
fn split_port(host: &str) -> (&str, Option<u16>) {
    let colon = if host.starts_with('[') {
        host.find(']')
            .and_then(|end| host[end..].starts_with("]:").then_some(end + 1))
    } else {
        host.rfind(':')
    };
    match colon {
        Some(i) => (&host[..i], host[i + 1..].parse().ok()),
        None => (host, None),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn address_literals_and_localhost_are_allowed_and_other_names_not() {
        let hosts = AllowedHosts::parse("");
        let table = [
            ("127.0.0.1:8080", true),
            ("localhost:8080", true),
            ("LocalHost:8080", true),
            ("[::1]:8080", true),
            ("192.168.1.20:8080", true),
            ("127.0.0.1:9090", true),
            ("127.0.0.1", true),
            ("::1", false),
            ("2130706433:8080", false),
            ("evil.example:8080", false),
            ("localhost.evil.example:8080", false),
            ("[::1", false),
            ("", false),
        ];
        for (host, allowed) in table {
            assert_eq!(hosts.allows(host), allowed, "{host}");
        }
    }

    #[test]
    fn configured_names_are_allowed_with_any_port_or_the_given_one() {
        let hosts = AllowedHosts::parse("stand-pc, balancer.plant:8443");
        let table = [
            ("stand-pc:8080", true),
            ("stand-pc", true),
            ("balancer.plant:8443", true),
            ("balancer.plant:8080", false),
            ("other:8080", false),
        ];
        for (host, allowed) in table {
            assert_eq!(hosts.allows(host), allowed, "{host}");
        }
        assert!(AllowedHosts::parse("*").allows("anything:1"));
    }

    /// An entry no `Host` header can equal (a URL, a path, a space, a port
    /// that is not one) is refused at start naming it: accepted, it made
    /// every request from that name a 421 with nothing said at start.
    #[test]
    fn an_entry_that_can_match_no_host_is_refused_naming_it() {
        for bad in [
            "http://stand-pc:8080",
            "stand-pc/",
            "stand pc",
            "stand-pc:80800",
            "stand-pc:",
            "[::1",
            "stand-pc:port",
        ] {
            let err = AllowedHosts::try_parse(&format!("ok-name, {bad}")).expect_err(bad);
            assert!(
                err.contains(&format!("'{bad}'")) && err.contains("--allowed-hosts"),
                "{err}"
            );
        }
        for good in [
            "",
            "*",
            "stand-pc",
            "stand-pc:8080",
            "Balancer.Plant:8443, [::1]:8080",
            "10.0.0.5",
            "host_1",
        ] {
            assert!(AllowedHosts::try_parse(good).is_ok(), "{good}");
        }
    }
}
